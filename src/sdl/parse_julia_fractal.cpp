// julia_fractal { <C> [quaternion | hypercomplex] [sqr | cube] [max_iteration N]
//                 [precision P] [slice <N>, D] [modifiers] } (povray 3.7; the
// items after the parameter in any order). Defaults as povray's:
// quaternion, sqr, max_iteration 20, precision 20, slice <0,0,0,1>, 0.
#include <fmt/format.h>

#include "scene/julia_fractal.h"
#include "sdl/interpreter.h"

namespace frameray::sdl {

std::shared_ptr<const scene::Shape> Interpreter::parseJuliaFractal(const Token& kind) {
    using Algebra = scene::JuliaFractal::Algebra;
    using Function = scene::JuliaFractal::Function;
    const Token paramAt = peek();
    const VectorValue param = toVector(parseExpression(), paramAt, 4);
    const std::array<double, 4> c = {param.v[0], param.v[1], param.v[2], param.v[3]};
    Algebra algebra = Algebra::Quaternion;
    Function function = Function::Sqr;
    Token functionAt = kind;
    double maxIterations = 20, precision = 20;
    for (;;) {
        const Token t = peek();
        switch (t.kw) {
            case Keyword::kw_quaternion:
                next();
                algebra = Algebra::Quaternion;
                continue;
            case Keyword::kw_hypercomplex:
                next();
                algebra = Algebra::Hypercomplex;
                continue;
            case Keyword::kw_sqr:
                next();
                function = Function::Sqr;
                continue;
            case Keyword::kw_cube:
                next();
                function = Function::Cube;
                functionAt = t;
                continue;
            case Keyword::kw_exp:
            case Keyword::kw_reciprocal:
            case Keyword::kw_sin:
            case Keyword::kw_asin:
            case Keyword::kw_sinh:
            case Keyword::kw_asinh:
            case Keyword::kw_cos:
            case Keyword::kw_acos:
            case Keyword::kw_cosh:
            case Keyword::kw_acosh:
            case Keyword::kw_tan:
            case Keyword::kw_atan:
            case Keyword::kw_tanh:
            case Keyword::kw_atanh:
            case Keyword::kw_ln:
            case Keyword::kw_pwr:
                unsupported(t, fmt::format("julia_fractal function '{}'", t.text));
            case Keyword::kw_max_iteration:
                next();
                maxIterations = parseFloat();
                continue;
            case Keyword::kw_precision:
                next();
                precision = parseFloat();
                continue;
            case Keyword::kw_slice: {
                next();
                const Token at = peek();
                const VectorValue n = toVector(parseExpression(), at, 4);
                accept(Sym::Comma);
                const double distance = parseFloat();
                if (n.v[0] != 0 || n.v[1] != 0 || n.v[2] != 0 || n.v[3] <= 0 || distance != 0)
                    unsupported(at, "julia_fractal slice other than <0, 0, 0, 1>, 0");
                continue;
            }
            default:
                break;
        }
        break;
    }
    // Cubing hypercomplex numbers does not give povray's shape (measured);
    // only their square is reproduced.
    if (algebra == Algebra::Hypercomplex && function == Function::Cube)
        unsupported(functionAt, "julia_fractal hypercomplex cube");
    if (maxIterations < 1) fail(kind, "julia_fractal needs max_iteration 1 or more");
    if (!(precision > 0)) fail(kind, "julia_fractal needs a precision above 0");
    return std::make_shared<scene::JuliaFractal>(c, algebra, function,
                                                 static_cast<int>(maxIterations), precision);
}

}  // namespace frameray::sdl
