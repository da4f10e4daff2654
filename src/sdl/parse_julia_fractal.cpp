// julia_fractal { <C> [quaternion | hypercomplex] [sqr | cube] [max_iteration N]
//                 [precision P] [slice <N>, D] [modifiers] } (povray 3.7; the
// items after the parameter in any order). Defaults as povray's:
// quaternion, sqr, max_iteration 20, precision 20, slice <0,0,0,1>, 0.
#include <fmt/format.h>

#include "scene/julia_fractal.h"
#include "sdl/builders.h"

namespace frameray::sdl {

std::shared_ptr<const scene::Shape> parseJuliaFractal(BuildContext& c, const Token& kind) {
    Reader& r = c.reader;
    using Algebra = scene::JuliaFractal::Algebra;
    using Function = scene::JuliaFractal::Function;
    const Token paramAt = r.peek();
    const VectorValue param = r.toVector(r.parseExpression(), paramAt, 4);
    const std::array<double, 4> constant = {param.v[0], param.v[1], param.v[2], param.v[3]};
    Algebra algebra = Algebra::Quaternion;
    Function function = Function::Sqr;
    double maxIterations = 20, precision = 20;
    for (;;) {
        const Token t = r.peek();
        switch (t.kw) {
            case Keyword::kw_quaternion:
                r.next();
                algebra = Algebra::Quaternion;
                continue;
            case Keyword::kw_hypercomplex:
                r.next();
                algebra = Algebra::Hypercomplex;
                continue;
            case Keyword::kw_sqr:
                r.next();
                function = Function::Sqr;
                continue;
            case Keyword::kw_cube:
                r.next();
                function = Function::Cube;
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
                r.unsupported(t, fmt::format("julia_fractal function '{}'", t.text));
            case Keyword::kw_max_iteration:
                r.next();
                maxIterations = r.parseFloat();
                continue;
            case Keyword::kw_precision:
                r.next();
                precision = r.parseFloat();
                continue;
            case Keyword::kw_slice: {
                r.next();
                const Token at = r.peek();
                const VectorValue n = r.toVector(r.parseExpression(), at, 4);
                r.accept(Sym::Comma);
                const double distance = r.parseFloat();
                if (n.v[0] != 0 || n.v[1] != 0 || n.v[2] != 0 || n.v[3] <= 0 || distance != 0)
                    r.unsupported(at, "julia_fractal slice other than <0, 0, 0, 1>, 0");
                continue;
            }
            default:
                break;
        }
        break;
    }
    if (maxIterations < 1) r.fail(kind, "julia_fractal needs max_iteration 1 or more");
    if (!(precision > 0)) r.fail(kind, "julia_fractal needs a precision above 0");
    return std::make_shared<scene::JuliaFractal>(constant, algebra, function,
                                                 static_cast<int>(maxIterations), precision);
}

}  // namespace frameray::sdl
