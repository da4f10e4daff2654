// Texture bodies and the map-based textures (seed 003 §5.4.4, the 3.7
// reference's texture_map): patterned textures (`texture { checker
// texture {..} texture {..} }`, `texture { gradient x texture_map { [v
// TEXTURE_BODY] .. } }`, `average`, `tiles { .. tile2 .. }`), declared maps
// of every kind (`#declare M = color_map { .. }`, used as `color_map { M }`),
// normal_map and slope_map entries.
#include <fmt/format.h>

#include "sdl/blend_map_value.h"
#include "sdl/builders.h"

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

// Defined below.
static void parseTextureBody(BuildContext& c, scene::Texture& tex, Sym closing);
static std::vector<scene::TextureMap::Entry> parseTextureMap(BuildContext& c);
static bool parseTexturePatternItem(BuildContext& c, scene::Texture& tex,
                                    std::shared_ptr<scene::TextureMap>& draft);

TexturePtr parseTexture(BuildContext& c, const scene::Texture* base) {
    Reader& r = c.reader;
    r.next();  // texture
    r.expect(Sym::LBrace, "'{' after 'texture'");
    scene::Texture tex = base ? *base : c.defaultTexture;
    parseTextureBody(c, tex, Sym::RBrace);
    r.expect(Sym::RBrace, "'}' closing 'texture'");
    return std::make_shared<const scene::Texture>(std::move(tex));
}

scene::Texture parseLayeredTextures(BuildContext& c, const scene::Texture* base,
                                    bool inDeclaration) {
    Reader& r = c.reader;
    scene::Texture tex = *parseTexture(c, base);
    // Further texture blocks right after it lie on top of it (seed 003
    // 5.4.5). In a #declare the look-ahead must not run the next line's
    // directive before the texture is bound, so it reads the raw token.
    auto layerFollows = [&] {
        return inDeclaration ? r.rawPeek().is(Keyword::kw_texture)
                             : r.peek().is(Keyword::kw_texture);
    };
    while (layerFollows()) {
        const Token layer = r.peek();
        scene::Texture upper = *parseTexture(c, nullptr);
        // povray 3.7 refuses both (measured), checking the lower first.
        if (tex.map) r.fail(layer, "Cannot layer over a patterned texture.");
        if (upper.map) r.fail(layer, "Cannot layer a patterned texture over another.");
        tex.stackOn(upper);
        tex = std::move(upper);
    }
    return tex;
}

static void parseTextureBody(BuildContext& c, scene::Texture& tex, Sym closing) {
    Reader& r = c.reader;
    const Token t = r.peek();
    const Reader::NestingGuard nesting(r, t);
    // Transformations after a uv-mapped texture identifier do nothing
    // (povray 3.7, measured); in the block that says uv_mapping they move
    // the uv pattern.
    bool uvFrozen = false;
    if (t.isIdentifier()) {
        r.next();
        const Value v = r.identifierValue(t);
        const auto* tp = std::get_if<TexturePtr>(&v);
        if (!tp) r.fail(t, fmt::format("'{}' is a {}, not a texture", t.text, valueKindName(v)));
        tex = **tp;
        uvFrozen = tex.uvMapping;
    }
    // The map of a patterned texture, edited in place while parsing.
    std::shared_ptr<scene::TextureMap> draft;
    if (tex.map) draft = std::make_shared<scene::TextureMap>(*tex.map);
    bool surfaceSeen = false;  // povray takes uv_mapping only before these
    while (!r.peek().is(closing)) {
        const Token item = r.peek();
        if (item.is(Keyword::kw_uv_mapping)) {
            if (surfaceSeen) r.fail(item, "Cannot parse input.");
            if (t.isIdentifier()) r.unsupported(item, "uv_mapping after a texture identifier");
            r.next();
            tex.uvMapping = true;
            continue;
        }
        Transform step;
        if (r.parseTransformation(step)) {
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
            r.fail(item, fmt::format("'{}' is not allowed in a patterned texture: give it to each "
                                     "texture of the map",
                                     item.text));
        if (item.is(Keyword::kw_pigment)) {
            tex.pigment = parseTexturePigment(c, tex);
        } else if (item.is(Keyword::kw_normal)) {
            tex.normal = parseTextureNormal(c, tex);
        } else if (item.is(Keyword::kw_finish)) {
            tex.finish = parseFinish(c, tex.finish.get());
        } else if (parseTexturePatternItem(c, tex, draft)) {
            continue;
        } else if (item.kind == TokenKind::Word && item.kw != Keyword::None) {
            r.unsupported(item, fmt::format("'{}' in texture", item.text));
        } else {
            r.fail(item, fmt::format("expected a texture item or '{}', found {}",
                                     closing == Sym::RBrace ? "}" : "]", describeToken(item)));
        }
    }
    tex.map = std::move(draft);
}

static bool parseTexturePatternItem(BuildContext& c, scene::Texture& tex,
                                    std::shared_ptr<scene::TextureMap>& draft) {
    Reader& r = c.reader;
    const Token item = r.peek();
    // Makes the texture a patterned one; transformations given before the
    // pattern move it.
    auto patterned = [&]() -> scene::TextureMap& {
        if (!draft) {
            if (tex.pigment && !tex.pigment->isSolid())
                r.fail(item, "a texture with a pigment cannot take a pattern of textures");
            draft = std::make_shared<scene::TextureMap>();
            if (!tex.transform.isIdentity()) draft->pattern.addTransform(tex.transform);
            tex.transform = Transform();
        }
        return *draft;
    };
    switch (item.kw) {
        case Keyword::kw_texture_map: {
            scene::TextureMap& map = patterned();
            if (map.mode == scene::TextureMap::Mode::List)
                r.fail(item, "a list pattern takes textures, not a texture_map");
            map.entries = parseTextureMap(c);
            // Transformations given between the pattern and its texture_map
            // move the map's textures too, as those after it do (measured:
            // `gradient y scale 10 texture_map { [0 T] [1 T] }` renders as
            // `gradient y texture_map { [0 T] [1 T] } scale 10`, T's own
            // patterns scaled).
            Transform before;
            for (const scene::Warp& w : map.pattern.chain)
                if (w.kind == scene::Warp::Kind::Transform) before = before.then(w.transform);
            if (!before.isIdentity())
                for (auto& e : map.entries) {
                    auto moved = std::make_shared<scene::Texture>(*e.texture);
                    moved->transformBy(before);
                    e.texture = std::move(moved);
                }
            return true;
        }
        case Keyword::kw_average: {
            r.next();
            patterned().mode = scene::TextureMap::Mode::Average;
            return true;
        }
        case Keyword::kw_tiles: {
            r.next();
            r.expect(Sym::LBrace, "'{' after 'tiles'");
            scene::TextureMap& map = patterned();
            map.pattern.kind = scene::PatternKind::Checker;
            map.mode = scene::TextureMap::Mode::List;
            // The first tile takes the checker's second cells (measured).
            map.entries.clear();
            const auto first = std::make_shared<const scene::Texture>(parseLayeredTextures(c));
            const Token tile2 = r.peek();
            if (!r.accept(Keyword::kw_tile2))
                r.fail(tile2,
                       fmt::format("expected 'tile2' in tiles, found {}", describeToken(tile2)));
            map.entries.push_back(
                {0, std::make_shared<const scene::Texture>(parseLayeredTextures(c))});
            map.entries.push_back({1, first});
            r.expect(Sym::RBrace, "'}' closing 'tiles'");
            return true;
        }
        case Keyword::kw_material_map: {
            r.next();
            scene::TextureMap& map = patterned();
            if (map.mode == scene::TextureMap::Mode::List)
                r.fail(item, "a list pattern takes textures, not a material_map");
            std::vector<std::shared_ptr<const scene::Texture>> textures;
            map.material = parseImageBlock(c, item, nullptr, &textures);
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
        case Keyword::kw_image_map:  // povray: only in a pigment
            r.fail(item, fmt::format("'{}' is not allowed in a texture", item.text));
        default:
            break;
    }
    if (isPatternKeyword(item)) {
        scene::TextureMap& map = patterned();
        parsePatternKeyword(c, map.pattern);
        if (!map.pattern.isList()) {
            if (map.mode == scene::TextureMap::Mode::List)
                map.mode = scene::TextureMap::Mode::Values;
            return true;
        }
        // A list pattern: one texture per index, commas optional; missing
        // ones are the default texture.
        map.mode = scene::TextureMap::Mode::List;
        map.entries.clear();
        const int count = scene::Pattern::listSize(map.pattern.kind);
        for (int i = 0; i < count; ++i) {
            if (i > 0) r.accept(Sym::Comma);
            std::shared_ptr<const scene::Texture> entry = std::make_shared<const scene::Texture>();
            if (r.peek().is(Keyword::kw_texture)) entry = parseTexture(c, nullptr);
            map.entries.push_back({static_cast<double>(i), std::move(entry)});
        }
        closeListPattern(c, map.pattern);
        return true;
    }
    // image_pattern and the pattern modifiers (turbulence, warps, waves...).
    return draft &&
           (parseImagePatternItem(c, draft->pattern) || parsePatternModifier(c, draft->pattern));
}

static std::vector<scene::TextureMap::Entry> parseTextureMap(BuildContext& c) {
    Reader& r = c.reader;
    const Token kw = r.next();  // texture_map
    r.expect(Sym::LBrace, "'{' after 'texture_map'");
    if (const BlendMapValue* m = blendMapIdentifier(c, BlendMapValue::Kind::Texture)) {
        r.expect(Sym::RBrace, "'}' after a texture_map identifier");
        return m->textures;
    }
    std::vector<scene::TextureMap::Entry> entries;
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        r.expect(Sym::LBracket, "'[' or '}' in texture_map");
        const double v = parseMapValue(c, true);
        r.accept(Sym::Comma);
        scene::Texture tex = c.defaultTexture;
        parseTextureBody(c, tex, Sym::RBracket);
        r.expect(Sym::RBracket, "']' after a texture_map entry");
        entries.push_back({v, std::make_shared<const scene::Texture>(std::move(tex))});
    }
    checkMapEntries(entries, kw, [&](const Token& at, const std::string& m) { r.fail(at, m); });
    return entries;
}

double parseMapValue(BuildContext& c, bool weightMayBeOmitted) {
    Reader& r = c.reader;
    // Entries of an average map may leave their weight out, which then is 1
    // (measured; the examples write `[pigment { Jade } finish { ... }]` and
    // `[gradient y color_map { ... }]`). povray knows it is the map of an
    // average; this takes any pigment, normal or texture map entry that
    // starts with its body, one of the keywords below.
    if (weightMayBeOmitted) {
        const Token t = r.peek();
        if (t.kind == TokenKind::Word && !t.isIdentifier() &&
            (isPatternKeyword(t) || t.is(Keyword::kw_pigment) || t.is(Keyword::kw_normal) ||
             t.is(Keyword::kw_finish) || t.is(Keyword::kw_texture) || t.is(Keyword::kw_image_map)))
            return 1.0;
    }
    // `[0 <1, 0, 0>]`: the value ends before the '<', as every expression
    // outside parentheses does.
    return r.parseFloat();
}

const BlendMapValue* blendMapIdentifier(BuildContext& c, BlendMapValue::Kind kind) {
    Reader& r = c.reader;
    const Token t = r.peek();
    if (!t.isIdentifier()) return nullptr;
    const Value* v = r.lookup(std::string(t.text));
    if (!v || !std::holds_alternative<BlendMapPtr>(*v)) return nullptr;
    r.next();
    const BlendMapValue& map = *std::get<BlendMapPtr>(*v);
    if (map.kind != kind) {
        BlendMapValue wanted;
        wanted.kind = kind;
        r.fail(t, fmt::format("'{}' is a {}, not a {}", t.text, map.kindName(), wanted.kindName()));
    }
    return &map;
}

Value parseBlendMapValue(BuildContext& c) {
    Reader& r = c.reader;
    auto map = std::make_shared<BlendMapValue>();
    switch (r.peek().kw) {
        case Keyword::kw_pigment_map:
            map->kind = BlendMapValue::Kind::Pigment;
            map->pigments = parsePigmentMap(c);
            break;
        case Keyword::kw_normal_map:
            map->kind = BlendMapValue::Kind::Normal;
            map->normals = parseNormalMap(c);
            break;
        case Keyword::kw_slope_map:
            map->kind = BlendMapValue::Kind::Slope;
            map->slopes = parseSlopeMap(c);
            break;
        case Keyword::kw_texture_map:
            map->kind = BlendMapValue::Kind::Texture;
            map->textures = parseTextureMap(c);
            break;
        default:
            map->kind = BlendMapValue::Kind::Color;
            map->colors = parseColorMap(c);
            break;
    }
    return BlendMapPtr(std::move(map));
}

std::vector<scene::Normal::MapEntry> parseNormalMap(BuildContext& c) {
    Reader& r = c.reader;
    const Token kw = r.next();  // normal_map
    r.expect(Sym::LBrace, "'{' after 'normal_map'");
    if (const BlendMapValue* m = blendMapIdentifier(c, BlendMapValue::Kind::Normal)) {
        r.expect(Sym::RBrace, "'}' after a normal_map identifier");
        return m->normals;
    }
    std::vector<scene::Normal::MapEntry> entries;
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        r.expect(Sym::LBracket, "'[' or '}' in normal_map");
        const double v = parseMapValue(c, true);
        r.accept(Sym::Comma);
        const Token body = r.peek();
        std::shared_ptr<const scene::Normal> normal = parseNormalBody(c, nullptr, Sym::RBracket);
        // povray: "No normal type given."
        if (!normal) r.fail(body, "a normal_map entry needs a normal pattern");
        if (normal->uvMapping) r.unsupported(body, "uv_mapping in a normal_map entry");
        r.expect(Sym::RBracket, "']' after a normal_map entry");
        entries.push_back({v, std::move(normal)});
    }
    checkMapEntries(entries, kw, [&](const Token& at, const std::string& m) { r.fail(at, m); });
    return entries;
}

std::vector<scene::Normal::SlopeEntry> parseSlopeMap(BuildContext& c) {
    Reader& r = c.reader;
    const Token kw = r.next();  // slope_map
    r.expect(Sym::LBrace, "'{' after 'slope_map'");
    if (const BlendMapValue* m = blendMapIdentifier(c, BlendMapValue::Kind::Slope)) {
        r.expect(Sym::RBrace, "'}' after a slope_map identifier");
        return m->slopes;
    }
    std::vector<scene::Normal::SlopeEntry> entries;
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        r.expect(Sym::LBracket, "'[' or '}' in slope_map");
        const double v = parseMapValue(c);
        r.accept(Sym::Comma);
        const Token at = r.peek();
        const Value hs = r.parseExpression();
        const VectorValue vec = r.toVector(hs, at, 2);
        r.expect(Sym::RBracket, "']' after a slope_map entry");
        entries.push_back({v, vec.v[0], vec.v[1]});
    }
    checkMapEntries(entries, kw, [&](const Token& at, const std::string& m) { r.fail(at, m); });
    return entries;
}

// #default { texture { } | pigment { } | normal { } | finish { } ... }:
// each block edits the default texture from its current state.
void parseDefaultDirective(BuildContext& c) {
    Reader& r = c.reader;
    r.expect(Sym::LBrace, "'{' after '#default'");
    while (!r.accept(Sym::RBrace)) {
        const Token t = r.peek();
        switch (t.kw) {
            case Keyword::kw_texture:
                c.defaultTexture = *parseTexture(c, &c.defaultTexture);
                break;
            case Keyword::kw_pigment:
                c.defaultTexture.pigment = parsePigment(c);
                break;
            case Keyword::kw_normal:
                c.defaultTexture.normal =
                    parseNormal(c, c.defaultTexture.normal.get(), &c.defaultNormal);
                break;
            case Keyword::kw_finish:
                c.defaultTexture.finish = parseFinish(c, c.defaultTexture.finish.get());
                break;
            default:
                r.fail(t, fmt::format(
                              "expected texture, pigment, normal or finish in #default, found {}",
                              describeToken(t)));
        }
        c.defaultTextureSet = true;
        c.placedDefaultTexture.reset();
    }
}

}  // namespace frameray::sdl
