// Transformations: translate, rotate, scale, matrix and transform { },
// read where any item takes them (objects, textures, patterns, lights).
#include <fmt/format.h>

#include <array>

#include "sdl/reader.h"

namespace frameray::sdl {

bool Reader::parseTransformation(Transform& out) {
    const Token t = peek();
    switch (t.kw) {
        case Keyword::kw_translate:
            next();
            out = Transform::translate(parseVec3());
            return true;
        case Keyword::kw_rotate:
            next();
            out = Transform::rotate(parseVec3());
            return true;
        case Keyword::kw_scale: {
            next();
            const Token at = peek();
            Vec3 s = parseVec3();
            for (int i = 0; i < 3; ++i)
                if (s[i] == 0) {
                    warn(at, "scale by zero in a component; changed to 1");
                    s[i] = 1;
                }
            out = Transform::scale(s);
            return true;
        }
        case Keyword::kw_matrix: {
            next();
            expect(Sym::Less, "'<' starting the 12 matrix values");
            std::array<double, 12> v{};
            for (int i = 0; i < 12; ++i) {
                if (i) accept(Sym::Comma);  // optional, as in povray
                v[i] = toFloat(parseAdditive(), t);
            }
            expect(Sym::Greater, "'>' closing the matrix");
            if (!Transform::fromMatrix(Matrix4::fromPovMatrix(v), out))
                fail(t, "this matrix is singular and cannot be used as a transformation");
            return true;
        }
        case Keyword::kw_transform:
            out = parseTransformBlock();
            return true;
        default:
            return false;
    }
}

Transform Reader::parseTransformBlock() {
    next();  // transform
    // `transform Ident` or `transform { [Ident] items... [inverse] }`.
    if (peek().isIdentifier()) {
        const Token id = next();
        const Value v = identifierValue(id);
        const auto* tp = std::get_if<TransformPtr>(&v);
        if (!tp) fail(id, fmt::format("'{}' is a {}, not a transform", id.text, valueKindName(v)));
        return **tp;
    }
    expect(Sym::LBrace, "'{' after 'transform'");
    Transform result;
    for (;;) {
        if (accept(Sym::RBrace)) break;
        if (accept(Keyword::kw_inverse)) {
            result = result.inverse();
            continue;
        }
        const Token t = peek();
        if (t.isIdentifier()) {
            next();
            const Value v = identifierValue(t);
            const auto* tp = std::get_if<TransformPtr>(&v);
            if (!tp)
                fail(t, fmt::format("'{}' is a {}, not a transform", t.text, valueKindName(v)));
            result = result.then(**tp);
            continue;
        }
        Transform step;
        if (!parseTransformation(step))
            fail(t, fmt::format("expected a transformation in 'transform', found {}",
                                describeToken(t)));
        result = result.then(step);
    }
    return result;
}

}  // namespace frameray::sdl
