// `material { [MATERIAL_IDENTIFIER] [texture { } ...] [interior { }]
// [TRANSFORMATIONS] }`: a texture and an interior given to an object
// together (povray 3.7). Transformations inside move the texture.
#include <fmt/format.h>

#include "sdl/builders.h"

namespace frameray::sdl {

MaterialPtr parseMaterial(BuildContext& c) {
    Reader& r = c.reader;
    const Token keyword = r.next();  // material
    r.expect(Sym::LBrace, "'{' after 'material'");
    MaterialValue m;
    const Token first = r.peek();
    if (first.isIdentifier()) {
        r.next();
        const Value v = r.identifierValue(first);
        const auto* mp = std::get_if<MaterialPtr>(&v);
        if (!mp)
            r.fail(first,
                   fmt::format("'{}' is a {}, not a material", first.text, valueKindName(v)));
        m = **mp;
    }
    std::optional<scene::Texture> texture;
    if (m.texture) texture = *m.texture;
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        Transform step;
        if (r.parseTransformation(step)) {
            if (texture) texture->transformBy(step);
            continue;
        }
        const Token t = r.peek();
        switch (t.kw) {
            case Keyword::kw_texture:
                // A material's texture starts afresh, as an object's first
                // texture block does.
                texture = parseLayeredTextures(c, nullptr);
                break;
            case Keyword::kw_interior:
                m.interior = parseInterior(c, m.interior.get());
                break;
            case Keyword::kw_interior_texture:
                r.unsupported(t, "interior_texture");
            default:
                r.fail(t, fmt::format("expected texture, interior or a transformation in '{}', "
                                      "found {}",
                                      keyword.text, describeToken(t)));
        }
    }
    if (texture) m.texture = std::make_shared<const scene::Texture>(std::move(*texture));
    return std::make_shared<const MaterialValue>(std::move(m));
}

}  // namespace frameray::sdl
