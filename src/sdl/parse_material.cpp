// `material { [MATERIAL_IDENTIFIER] [texture { } ...] [interior { }]
// [TRANSFORMATIONS] }`: a texture and an interior given to an object
// together (povray 3.7). Transformations inside move the texture.
#include <fmt/format.h>

#include "sdl/interpreter.h"

namespace frameray::sdl {

MaterialPtr Interpreter::parseMaterial() {
    const Token keyword = next();  // material
    expect(Sym::LBrace, "'{' after 'material'");
    MaterialValue m;
    const Token first = peek();
    if (first.isIdentifier()) {
        next();
        const Value v = identifierValue(first);
        const auto* mp = std::get_if<MaterialPtr>(&v);
        if (!mp)
            fail(first, fmt::format("'{}' is a {}, not a material", first.text, valueKindName(v)));
        m = **mp;
    }
    std::optional<scene::Texture> texture;
    if (m.texture) texture = *m.texture;
    for (;;) {
        if (accept(Sym::RBrace)) break;
        Transform step;
        if (parseTransformation(step)) {
            if (texture) texture->transformBy(step);
            continue;
        }
        const Token t = peek();
        switch (t.kw) {
            case Keyword::kw_texture:
                // A material's texture starts afresh, as an object's first
                // texture block does.
                texture = parseLayeredTextures(nullptr);
                break;
            case Keyword::kw_interior:
                m.interior = parseInterior(m.interior.get());
                break;
            case Keyword::kw_interior_texture:
                unsupported(t, "interior_texture");
            default:
                fail(t, fmt::format("expected texture, interior or a transformation in '{}', "
                                    "found {}",
                                    keyword.text, describeToken(t)));
        }
    }
    if (texture) m.texture = std::make_shared<const scene::Texture>(std::move(*texture));
    return std::make_shared<const MaterialValue>(std::move(m));
}

}  // namespace frameray::sdl
