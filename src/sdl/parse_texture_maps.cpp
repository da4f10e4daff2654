// Texture bodies and the map-based textures (seed 003 §5.4.4, the 3.7
// reference's texture_map): patterned textures (`texture { checker
// texture {..} texture {..} }`, `texture { gradient x texture_map { [v
// TEXTURE_BODY] .. } }`, `average`, `tiles { .. tile2 .. }`), declared maps
// of every kind (`#declare M = color_map { .. }`, used as `color_map { M }`),
// normal_map and slope_map entries.
#include <fmt/format.h>

#include "sdl/blend_map_value.h"
#include "sdl/interpreter.h"

namespace frameray::sdl {

const char* BlendMapValue::kindName() const {
    switch (kind) {
        case Kind::Color:
            return "color_map";
        case Kind::Pigment:
            return "pigment_map";
        case Kind::Normal:
            return "normal_map";
        case Kind::Slope:
            return "slope_map";
        case Kind::Texture:
            return "texture_map";
    }
    return "map";
}

namespace {

// A map needs an entry; povray allows at most 256. The values are not
// checked for order: under `average` they are weights.
template <typename Entries, typename Fail>
void checkMapEntries(const Entries& entries, const Token& kw, Fail&& fail) {
    if (entries.empty()) fail(kw, fmt::format("{} needs at least one entry", kw.text));
    if (entries.size() > scene::ColorMap::kMaxEntries)
        fail(kw,
             fmt::format("a {} holds at most {} entries", kw.text, scene::ColorMap::kMaxEntries));
}

}  // namespace

TexturePtr Interpreter::parseTexture(const scene::Texture* base) {
    next();  // texture
    expect(Sym::LBrace, "'{' after 'texture'");
    scene::Texture tex = base ? *base : defaultTexture_;
    parseTextureBody(tex, Sym::RBrace);
    expect(Sym::RBrace, "'}' closing 'texture'");
    return std::make_shared<const scene::Texture>(std::move(tex));
}

scene::Texture Interpreter::parseLayeredTextures(const scene::Texture* base, bool inDeclaration) {
    scene::Texture tex = *parseTexture(base);
    // Further texture blocks right after it lie on top of it (seed 003
    // 5.4.5). In a #declare the look-ahead must not run the next line's
    // directive before the texture is bound, so it reads the raw token.
    auto layerFollows = [&] {
        return inDeclaration ? rawPeek().is(Keyword::kw_texture) : peek().is(Keyword::kw_texture);
    };
    while (layerFollows()) {
        const Token layer = peek();
        scene::Texture upper = *parseTexture(nullptr);
        // povray 3.7 refuses both (measured), checking the lower first.
        if (tex.map) fail(layer, "Cannot layer over a patterned texture.");
        if (upper.map) fail(layer, "Cannot layer a patterned texture over another.");
        tex.stackOn(upper);
        tex = std::move(upper);
    }
    return tex;
}

void Interpreter::parseTextureBody(scene::Texture& tex, Sym closing) {
    const Token t = peek();
    const NestingGuard nesting(*this, t);
    // Transformations after a uv-mapped texture identifier do nothing
    // (povray 3.7, measured); in the block that says uv_mapping they move
    // the uv pattern.
    bool uvFrozen = false;
    if (t.isIdentifier()) {
        next();
        const Value v = identifierValue(t);
        const auto* tp = std::get_if<TexturePtr>(&v);
        if (!tp) fail(t, fmt::format("'{}' is a {}, not a texture", t.text, valueKindName(v)));
        tex = **tp;
        uvFrozen = tex.uvMapping;
    }
    // The map of a patterned texture, edited in place while parsing.
    std::shared_ptr<scene::TextureMap> draft;
    if (tex.map) draft = std::make_shared<scene::TextureMap>(*tex.map);
    bool surfaceSeen = false;  // povray takes uv_mapping only before these
    while (!peek().is(closing)) {
        const Token item = peek();
        if (item.is(Keyword::kw_uv_mapping)) {
            if (surfaceSeen) fail(item, "Cannot parse input.");
            if (t.isIdentifier()) unsupported(item, "uv_mapping after a texture identifier");
            next();
            tex.uvMapping = true;
            continue;
        }
        Transform step;
        if (parseTransformation(step)) {
            if (uvFrozen) {
                tex.transformBy(step);  // turns the normal's perturbation only
                continue;
            }
            // A transformation moves the pattern and the textures the map
            // holds so far (povray transforms them at this point), and
            // every layer of a layered texture named here (measured:
            // texture { LAYERED rotate y*90 } turns all its layers).
            if (draft)
                draft->transformBy(step);
            else
                tex.transformBy(step);
            continue;
        }
        const bool surfaceItem = item.is(Keyword::kw_pigment) || item.is(Keyword::kw_normal) ||
                                 item.is(Keyword::kw_finish);
        surfaceSeen = surfaceSeen || surfaceItem;
        if (surfaceItem && draft)
            fail(item, fmt::format("'{}' is not allowed in a patterned texture: give it to each "
                                   "texture of the map",
                                   item.text));
        if (item.is(Keyword::kw_pigment)) {
            tex.pigment = parseTexturePigment(tex);
        } else if (item.is(Keyword::kw_normal)) {
            tex.normal = parseTextureNormal(tex);
        } else if (item.is(Keyword::kw_finish)) {
            tex.finish = *parseFinish(&tex.finish);
        } else if (parseTexturePatternItem(tex, draft)) {
            continue;
        } else if (item.kind == TokenKind::Word && item.kw != Keyword::None) {
            unsupported(item, fmt::format("'{}' in texture", item.text));
        } else {
            fail(item, fmt::format("expected a texture item or '{}', found {}",
                                   closing == Sym::RBrace ? "}" : "]", describeToken(item)));
        }
    }
    tex.map = std::move(draft);
}

bool Interpreter::parseTexturePatternItem(scene::Texture& tex,
                                          std::shared_ptr<scene::TextureMap>& draft) {
    const Token item = peek();
    // Makes the texture a patterned one; transformations given before the
    // pattern move it.
    auto patterned = [&]() -> scene::TextureMap& {
        if (!draft) {
            if (tex.pigment && !tex.pigment->isSolid())
                fail(item, "a texture with a pigment cannot take a pattern of textures");
            draft = std::make_shared<scene::TextureMap>();
            if (!tex.transform.isIdentity()) draft->holder.transform(tex.transform);
            tex.transform = Transform();
        }
        return *draft;
    };
    switch (item.kw) {
        case Keyword::kw_texture_map: {
            scene::TextureMap& map = patterned();
            if (map.mode == scene::TextureMap::Mode::List)
                fail(item, "a list pattern takes textures, not a texture_map");
            map.entries = parseTextureMap();
            return true;
        }
        case Keyword::kw_average: {
            next();
            patterned().mode = scene::TextureMap::Mode::Average;
            return true;
        }
        case Keyword::kw_tiles: {
            next();
            expect(Sym::LBrace, "'{' after 'tiles'");
            scene::TextureMap& map = patterned();
            scene::Pattern pattern = map.holder.pattern();
            pattern.kind = scene::PatternKind::Checker;
            map.holder.setPattern(pattern);
            map.mode = scene::TextureMap::Mode::List;
            // The first tile takes the checker's second cells (measured).
            map.entries.clear();
            const auto first = std::make_shared<const scene::Texture>(parseLayeredTextures());
            const Token tile2 = peek();
            if (!accept(Keyword::kw_tile2))
                fail(tile2,
                     fmt::format("expected 'tile2' in tiles, found {}", describeToken(tile2)));
            map.entries.push_back(
                {0, std::make_shared<const scene::Texture>(parseLayeredTextures())});
            map.entries.push_back({1, first});
            expect(Sym::RBrace, "'}' closing 'tiles'");
            return true;
        }
        case Keyword::kw_material_map: {
            next();
            scene::TextureMap& map = patterned();
            if (map.mode == scene::TextureMap::Mode::List)
                fail(item, "a list pattern takes textures, not a material_map");
            std::vector<std::shared_ptr<const scene::Texture>> textures;
            map.material = parseImageBlock(item, nullptr, &textures);
            map.mode = scene::TextureMap::Mode::Material;
            map.entries.clear();
            for (auto& t : textures)
                map.entries.push_back({static_cast<double>(map.entries.size()), std::move(t)});
            return true;
        }
        case Keyword::kw_color_map:
        case Keyword::kw_colour_map:
        case Keyword::kw_pigment_map:
        case Keyword::kw_normal_map:
        case Keyword::kw_slope_map:
            fail(item, fmt::format("'{}' is not allowed in a texture", item.text));
        default:
            break;
    }
    if (isPatternKeyword(item)) {
        scene::TextureMap& map = patterned();
        parsePatternKeyword(map.holder);
        if (!map.holder.pattern().isList()) {
            if (map.mode == scene::TextureMap::Mode::List)
                map.mode = scene::TextureMap::Mode::Values;
            return true;
        }
        // A list pattern: one texture per index, commas optional; missing
        // ones are the default texture.
        map.mode = scene::TextureMap::Mode::List;
        map.entries.clear();
        const int count = scene::Pattern::listSize(map.holder.pattern().kind);
        for (int i = 0; i < count; ++i) {
            if (i > 0) accept(Sym::Comma);
            std::shared_ptr<const scene::Texture> entry = std::make_shared<const scene::Texture>();
            if (peek().is(Keyword::kw_texture)) entry = parseTexture(nullptr);
            map.entries.push_back({static_cast<double>(i), std::move(entry)});
        }
        closeListPattern(map.holder.pattern());
        return true;
    }
    // Pattern modifiers (turbulence, warps, wave types...).
    return draft && parsePigmentPatternItem(draft->holder);
}

std::vector<scene::TextureMap::Entry> Interpreter::parseTextureMap() {
    const Token kw = next();  // texture_map
    expect(Sym::LBrace, "'{' after 'texture_map'");
    if (const BlendMapValue* m = blendMapIdentifier(BlendMapValue::Kind::Texture)) {
        expect(Sym::RBrace, "'}' after a texture_map identifier");
        return m->textures;
    }
    std::vector<scene::TextureMap::Entry> entries;
    for (;;) {
        if (accept(Sym::RBrace)) break;
        expect(Sym::LBracket, "'[' or '}' in texture_map");
        const double v = parseMapValue(true);
        accept(Sym::Comma);
        scene::Texture tex = defaultTexture_;
        parseTextureBody(tex, Sym::RBracket);
        expect(Sym::RBracket, "']' after a texture_map entry");
        entries.push_back({v, std::make_shared<const scene::Texture>(std::move(tex))});
    }
    checkMapEntries(entries, kw, [&](const Token& at, const std::string& m) { fail(at, m); });
    return entries;
}

double Interpreter::parseMapValue(bool weightMayBeOmitted) {
    // Entries of an average map may leave their weight out, which then is 1
    // (measured; the examples write `[pigment { Jade } finish { ... }]` and
    // `[gradient y color_map { ... }]`). povray knows it is the map of an
    // average; this takes any pigment, normal or texture map entry that
    // starts with its body, one of the keywords below.
    if (weightMayBeOmitted) {
        const Token t = peek();
        if (t.kind == TokenKind::Word && !t.isIdentifier() &&
            (isPatternKeyword(t) || t.is(Keyword::kw_pigment) || t.is(Keyword::kw_normal) ||
             t.is(Keyword::kw_finish) || t.is(Keyword::kw_texture) || t.is(Keyword::kw_image_map)))
            return 1.0;
    }
    // `[0 <1, 0, 0>]`: the value ends before the '<', as every expression
    // outside parentheses does.
    return parseFloat();
}

const BlendMapValue* Interpreter::blendMapIdentifier(BlendMapValue::Kind kind) {
    const Token t = peek();
    if (!t.isIdentifier()) return nullptr;
    const Value* v = lookup(std::string(t.text));
    if (!v || !std::holds_alternative<BlendMapPtr>(*v)) return nullptr;
    next();
    const BlendMapValue& map = *std::get<BlendMapPtr>(*v);
    if (map.kind != kind) {
        BlendMapValue wanted;
        wanted.kind = kind;
        fail(t, fmt::format("'{}' is a {}, not a {}", t.text, map.kindName(), wanted.kindName()));
    }
    return &map;
}

Value Interpreter::parseBlendMapValue() {
    auto map = std::make_shared<BlendMapValue>();
    switch (peek().kw) {
        case Keyword::kw_pigment_map:
            map->kind = BlendMapValue::Kind::Pigment;
            map->pigments = parsePigmentMap();
            break;
        case Keyword::kw_normal_map:
            map->kind = BlendMapValue::Kind::Normal;
            map->normals = parseNormalMap();
            break;
        case Keyword::kw_slope_map:
            map->kind = BlendMapValue::Kind::Slope;
            map->slopes = parseSlopeMap();
            break;
        case Keyword::kw_texture_map:
            map->kind = BlendMapValue::Kind::Texture;
            map->textures = parseTextureMap();
            break;
        default:
            map->kind = BlendMapValue::Kind::Color;
            map->colors = parseColorMap();
            break;
    }
    return BlendMapPtr(std::move(map));
}

std::vector<scene::Normal::MapEntry> Interpreter::parseNormalMap() {
    const Token kw = next();  // normal_map
    expect(Sym::LBrace, "'{' after 'normal_map'");
    if (const BlendMapValue* m = blendMapIdentifier(BlendMapValue::Kind::Normal)) {
        expect(Sym::RBrace, "'}' after a normal_map identifier");
        return m->normals;
    }
    std::vector<scene::Normal::MapEntry> entries;
    for (;;) {
        if (accept(Sym::RBrace)) break;
        expect(Sym::LBracket, "'[' or '}' in normal_map");
        const double v = parseMapValue(true);
        accept(Sym::Comma);
        const Token body = peek();
        std::shared_ptr<const scene::Normal> normal = parseNormalBody(nullptr, Sym::RBracket);
        // povray: "No normal type given."
        if (!normal) fail(body, "a normal_map entry needs a normal pattern");
        if (normal->uvMapping) unsupported(body, "uv_mapping in a normal_map entry");
        expect(Sym::RBracket, "']' after a normal_map entry");
        entries.push_back({v, std::move(normal)});
    }
    checkMapEntries(entries, kw, [&](const Token& at, const std::string& m) { fail(at, m); });
    return entries;
}

std::vector<scene::Normal::SlopeEntry> Interpreter::parseSlopeMap() {
    const Token kw = next();  // slope_map
    expect(Sym::LBrace, "'{' after 'slope_map'");
    if (const BlendMapValue* m = blendMapIdentifier(BlendMapValue::Kind::Slope)) {
        expect(Sym::RBrace, "'}' after a slope_map identifier");
        return m->slopes;
    }
    std::vector<scene::Normal::SlopeEntry> entries;
    for (;;) {
        if (accept(Sym::RBrace)) break;
        expect(Sym::LBracket, "'[' or '}' in slope_map");
        const double v = parseMapValue();
        accept(Sym::Comma);
        const Token at = peek();
        const Value hs = parseExpression();
        const VectorValue vec = toVector(hs, at, 2);
        expect(Sym::RBracket, "']' after a slope_map entry");
        entries.push_back({v, vec.v[0], vec.v[1]});
    }
    checkMapEntries(entries, kw, [&](const Token& at, const std::string& m) { fail(at, m); });
    return entries;
}

// #default { texture { } | pigment { } | normal { } | finish { } ... }:
// each block edits the default texture from its current state.
void Interpreter::directiveDefault() {
    expect(Sym::LBrace, "'{' after '#default'");
    while (!accept(Sym::RBrace)) {
        const Token t = peek();
        switch (t.kw) {
            case Keyword::kw_texture:
                defaultTexture_ = *parseTexture(&defaultTexture_);
                break;
            case Keyword::kw_pigment:
                defaultTexture_.pigment = parsePigment();
                break;
            case Keyword::kw_normal:
                defaultTexture_.normal = parseNormal(defaultTexture_.normal.get(), &defaultNormal_);
                break;
            case Keyword::kw_finish:
                defaultTexture_.finish = *parseFinish(&defaultTexture_.finish);
                break;
            default:
                fail(t, fmt::format(
                            "expected texture, pigment, normal or finish in #default, found {}",
                            describeToken(t)));
        }
        defaultTextureSet_ = true;
    }
}

}  // namespace frameray::sdl
