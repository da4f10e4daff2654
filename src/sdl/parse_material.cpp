// material { }: a texture and an interior carried together, as the
// include files declare their glasses (textures.inc M_Glass and others).
#include <fmt/format.h>

#include "sdl/interpreter.h"

namespace frameray::sdl {

MaterialPtr Interpreter::parseMaterial() {
    next();  // material
    expect(Sym::LBrace, "'{' after 'material'");
    MaterialValue m;
    if (peek().isIdentifier()) {
        const Token id = next();
        const Value v = identifierValue(id);
        const auto* mp = std::get_if<MaterialPtr>(&v);
        if (!mp) fail(id, fmt::format("'{}' is a {}, not a material", id.text, valueKindName(v)));
        m = **mp;
    }
    for (;;) {
        if (accept(Sym::RBrace)) break;
        Transform step;
        if (parseTransformation(step)) {
            // Moves the texture given so far; an interior has nothing that
            // a transformation changes until media exist.
            if (m.texture) {
                scene::Texture moved = *m.texture;
                moved.transformBy(step);
                m.texture = std::make_shared<const scene::Texture>(std::move(moved));
            }
            continue;
        }
        const Token t = peek();
        if (t.is(Keyword::kw_texture)) {
            m.texture = std::make_shared<const scene::Texture>(parseLayeredTextures());
        } else if (t.is(Keyword::kw_interior)) {
            m.interior = parseInterior(m.interior.get());
        } else {
            fail(t, fmt::format("expected texture, interior, a transformation or '}}' in material, "
                                "found {}",
                                describeToken(t)));
        }
    }
    return std::make_shared<const MaterialValue>(std::move(m));
}

}  // namespace frameray::sdl
