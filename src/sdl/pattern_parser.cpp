// Pigments and their patterns: pigment { }, colour lists, colour and
// pigment maps, pattern modifiers, turbulence and warps (seed 003 §5.4.1).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <utility>

#include "sdl/builders.h"
#include "sdl/function_value.h"

namespace frameray::sdl {

namespace {

bool startsColor(const Token& t) {
    return t.isIdentifier() || t.is(Sym::Less) || t.kind == TokenKind::Number ||
           t.is(Keyword::kw_color) || t.is(Keyword::kw_colour) || t.is(Keyword::kw_rgb) ||
           t.is(Keyword::kw_rgbf) || t.is(Keyword::kw_rgbt) || t.is(Keyword::kw_rgbft) ||
           t.is(Keyword::kw_srgb) || t.is(Keyword::kw_srgbf) || t.is(Keyword::kw_srgbt) ||
           t.is(Keyword::kw_srgbft) || t.is(Keyword::kw_red) || t.is(Keyword::kw_green) ||
           t.is(Keyword::kw_blue) || t.is(Keyword::kw_filter) || t.is(Keyword::kw_transmit) ||
           t.is(Sym::LParen);
}

// Pattern keywords that take a colour list or a colour map, and their
// default colours (POV-Ray's: checker blue/green, hexagon blue/green/red,
// brick grey mortar and red brick).
std::optional<scene::PatternKind> patternKeyword(Keyword k) {
    using scene::PatternKind;
    switch (k) {
        case Keyword::kw_checker:
            return PatternKind::Checker;
        case Keyword::kw_hexagon:
            return PatternKind::Hexagon;
        case Keyword::kw_brick:
            return PatternKind::Brick;
        case Keyword::kw_square:
            return PatternKind::Square;
        case Keyword::kw_triangular:
            return PatternKind::Triangular;
        case Keyword::kw_cubic:
            return PatternKind::Cubic;
        case Keyword::kw_gradient:
            return PatternKind::Gradient;
        case Keyword::kw_onion:
            return PatternKind::Onion;
        case Keyword::kw_radial:
            return PatternKind::Radial;
        case Keyword::kw_spherical:
            return PatternKind::Spherical;
        case Keyword::kw_cylindrical:
            return PatternKind::Cylindrical;
        case Keyword::kw_planar:
            return PatternKind::Planar;
        case Keyword::kw_boxed:
            return PatternKind::Boxed;
        case Keyword::kw_leopard:
            return PatternKind::Leopard;
        case Keyword::kw_bozo:
            return PatternKind::Bozo;
        case Keyword::kw_spotted:
            return PatternKind::Spotted;
        case Keyword::kw_bumps:
            return PatternKind::Bumps;
        case Keyword::kw_dents:
            return PatternKind::Dents;
        case Keyword::kw_granite:
            return PatternKind::Granite;
        case Keyword::kw_marble:
            return PatternKind::Marble;
        case Keyword::kw_wood:
            return PatternKind::Wood;
        case Keyword::kw_agate:
            return PatternKind::Agate;
        case Keyword::kw_wrinkles:
            return PatternKind::Wrinkles;
        case Keyword::kw_ripples:
            return PatternKind::Ripples;
        case Keyword::kw_waves:
            return PatternKind::Waves;
        case Keyword::kw_function:
            return PatternKind::Function;
        case Keyword::kw_crackle:
            return PatternKind::Crackle;
        case Keyword::kw_mandel:
        case Keyword::kw_julia:
        case Keyword::kw_magnet:
            return PatternKind::Fractal;
        case Keyword::kw_quilted:
            return PatternKind::Quilted;
        case Keyword::kw_spiral1:
            return PatternKind::Spiral1;
        case Keyword::kw_spiral2:
            return PatternKind::Spiral2;
        case Keyword::kw_cells:
            return PatternKind::Cells;
        case Keyword::kw_pigment_pattern:
            return PatternKind::PigmentPattern;
        case Keyword::kw_object:
            return PatternKind::Object;
        case Keyword::kw_facets:
            return PatternKind::Facets;
        case Keyword::kw_density_file:
            return PatternKind::DensityFile;
        case Keyword::kw_slope:
            return PatternKind::Slope;
        case Keyword::kw_aoi:
            return PatternKind::Aoi;
        case Keyword::kw_tiling:
            return PatternKind::Tiling;
        case Keyword::kw_pavement:
            return PatternKind::Pavement;
        default:
            return std::nullopt;
    }
}

// The wave keywords without arguments (poly_wave takes an exponent).
std::optional<scene::WaveType> waveKeyword(Keyword kw) {
    switch (kw) {
        case Keyword::kw_ramp_wave:
            return scene::WaveType::Ramp;
        case Keyword::kw_triangle_wave:
            return scene::WaveType::Triangle;
        case Keyword::kw_sine_wave:
            return scene::WaveType::Sine;
        case Keyword::kw_scallop_wave:
            return scene::WaveType::Scallop;
        case Keyword::kw_cubic_wave:
            return scene::WaveType::Cubic;
        default:
            return std::nullopt;
    }
}

std::vector<Color> defaultListColors(scene::PatternKind kind) {
    using scene::PatternKind;
    const Color blue(RGB(0, 0, 1)), green(RGB(0, 1, 0)), red(RGB(1, 0, 0));
    switch (kind) {
        case PatternKind::Checker:
        case PatternKind::Object:  // outside, inside (measured)
            return {blue, green};
        case PatternKind::Hexagon:
            return {blue, green, red};
        case PatternKind::Brick:
            return {Color(RGB(0.5)), Color(RGB(0.6, 0.15, 0.15))};
        // square, triangular and cubic: red, green, blue, yellow, cyan,
        // magenta (measured).
        case PatternKind::Square:
            return {red, green, blue, Color(RGB(1, 1, 0))};
        case PatternKind::Triangular:
        case PatternKind::Cubic:
            return {
                red, green, blue, Color(RGB(1, 1, 0)), Color(RGB(0, 1, 1)), Color(RGB(1, 0, 1))};
        default:
            return {};
    }
}

// The patterns whose values depend on the noise generator (a global
// noise_generator after one of them cannot be applied to it). Others, like
// functions.inc's f_hexagon pigment, may come before global_settings.
bool readsNoiseGenerator(scene::PatternKind kind) {
    using K = scene::PatternKind;
    switch (kind) {
        case K::Bozo:
        case K::Spotted:
        case K::Bumps:
        case K::Dents:
        case K::Granite:
        case K::Marble:
        case K::Agate:
        case K::Wrinkles:
        case K::Crackle:
            return true;
        default:
            return false;
    }
}

}  // namespace

// Defined below.
static void checkPavement(BuildContext& c, const scene::Pattern& pattern, const Token& at);
static void parseFractalHead(BuildContext& c, const Token& kind, scene::FractalSettings& f);
static void parseFractalItem(BuildContext& c, const Token& item, scene::FractalSettings& f);

static void parsePigmentBody(BuildContext& c, scene::Pigment& result, Sym closing);
static void parseSlopeArguments(BuildContext& c, scene::Pattern& pattern);
static scene::Warp parseWarp(BuildContext& c);
static bool parsePatternSetting(BuildContext& c, scene::Pattern& pattern);
static void parsePavementItem(BuildContext& c, scene::PavementSettings& s);

PigmentPtr parsePigment(BuildContext& c, const scene::Pigment* base) {
    Reader& r = c.reader;
    r.next();  // pigment
    r.expect(Sym::LBrace, "'{' after 'pigment'");
    // povray edits the pigment a texture already has (measured:
    // texture { T pigment { scale 0.3 } } scales T's checker).
    auto result = std::make_shared<scene::Pigment>(base ? *base : *c.defaultTexture.pigment);
    parsePigmentBody(c, *result, Sym::RBrace);
    r.expect(Sym::RBrace, "'}' closing 'pigment'");
    return result;
}

static void parsePigmentBody(BuildContext& c, scene::Pigment& result, Sym closing) {
    Reader& r = c.reader;
    const Token t = r.peek();
    const Reader::NestingGuard nesting(r, t);
    // uv_mapping (povray 3.7, measured): first in the block, maybe followed
    // by an identifier; the block's transformations then move the uv
    // pattern, while those after a uv-mapped identifier do nothing.
    bool uvFrozen = false;
    auto copyIdentifier = [&] {
        const Token id = r.peek();
        if (!id.isIdentifier()) return false;
        const Value* v = r.lookup(std::string(id.text));
        // A pigment identifier, or an element of an array of pigments
        // (`pigment { Pigments[I] }`, the example portfolio).
        if (!v || !(std::holds_alternative<PigmentPtr>(*v) || arrayHolds<PigmentPtr>(*v)))
            return false;
        r.next();
        const Value declared = r.identifierValue(id, v);
        const auto* pigment = std::get_if<PigmentPtr>(&declared);
        if (!pigment)
            r.fail(id, fmt::format("expected a pigment, found a {}", valueKindName(declared)));
        result = **pigment;
        return true;
    };
    if (copyIdentifier()) {
        uvFrozen = result.uvMapping();
        if (r.peek().is(Keyword::kw_uv_mapping))
            r.unsupported(r.peek(), "uv_mapping after a pigment identifier");
    } else if (r.accept(Keyword::kw_uv_mapping)) {
        copyIdentifier();
        result.setUvMapping();
    }
    while (!r.peek().is(closing)) {
        const Token item = r.peek();
        Transform step;
        if (r.parseTransformation(step)) {
            if (!uvFrozen) result.transform(step);
            continue;
        }
        if (item.is(Keyword::kw_quick_color) || item.is(Keyword::kw_quick_colour)) {
            r.next();
            result.setQuickColor(r.parseColor());
            continue;
        }
        if (item.is(Keyword::kw_uv_mapping))
            r.unsupported(item, "uv_mapping after other pigment items");
        if (parsePigmentPatternItem(c, result)) continue;
        if (startsColor(item)) {
            result.setSolid(r.parseColor());
            continue;
        }
        if (item.kind == TokenKind::Word && item.kw != Keyword::None)
            r.unsupported(item, fmt::format("'{}' in pigment", item.text));
        r.fail(item,
               fmt::format("expected a color or pigment item, found {}", describeToken(item)));
    }
    checkPavement(c, std::as_const(result).pattern(), r.peek());
    result.settleDefaultColorMap();
}

static PigmentPtr parsePigmentListEntry(BuildContext& c) {
    Reader& r = c.reader;
    const Token t = r.peek();
    if (t.is(Keyword::kw_pigment)) return parsePigment(c);
    if (t.isIdentifier()) {
        const Value* v = r.lookup(std::string(t.text));
        if (v && std::holds_alternative<PigmentPtr>(*v)) {
            r.next();
            return std::get<PigmentPtr>(*v);
        }
    }
    return std::make_shared<const scene::Pigment>(r.parseColor());
}

bool isPatternKeyword(const Token& t) {
    return patternKeyword(t.kw).has_value();
}

void parsePatternKeyword(BuildContext& c, scene::Pattern& pattern, bool inNormal) {
    Reader& r = c.reader;
    const Token item = r.next();
    const scene::PatternKind kind = *patternKeyword(item.kw);
    if (kind == scene::PatternKind::Facets && !inNormal)
        r.fail(item, "'facets' can only be used in a normal");
    pattern.kind = kind;
    if (!pattern.noiseGeneratorGiven) pattern.noiseGenerator = r.noiseGenerator();
    if (readsNoiseGenerator(kind)) r.noteNoiseGeneratorUse();
    if (kind == scene::PatternKind::Ripples || kind == scene::PatternKind::Waves)
        pattern.waves = r.waveSources();
    if (kind == scene::PatternKind::Gradient) {
        const Vec3 g = r.parseVec3();
        const double len = length(g);
        if (len == 0) r.fail(item, "gradient vector is zero");
        pattern.gradient = g * (1.0 / len);
    } else if (kind == scene::PatternKind::Spiral1 || kind == scene::PatternKind::Spiral2) {
        // The number of arms is truncated to a whole number (measured);
        // spirals default to the triangle wave like marble and wood.
        pattern.arms = static_cast<int>(r.parseFloat());
        pattern.waveType = scene::WaveType::Triangle;
    } else if (kind == scene::PatternKind::Fractal) {
        parseFractalHead(c, item, pattern.fractal);
    } else if (kind == scene::PatternKind::Function) {
        pattern.function = r.parseXyzFunction(item);
    } else if (kind == scene::PatternKind::Slope) {
        parseSlopeArguments(c, pattern);
    } else if (kind == scene::PatternKind::Tiling) {
        // tiling N: truncated like povray's other counts (measured: 1.9 is 1).
        const Token at = r.peek();
        const double n = r.parseFloat();
        const int number = static_cast<int>(n);
        if (number < 1 || number > 27) r.fail(at, "Tiling number must be between 1 and 27.");
        if (!scene::tilingSupported(number)) r.unsupported(at, fmt::format("tiling {}", number));
        pattern.tiling = number;
    } else if (kind == scene::PatternKind::DensityFile) {
        // density_file df3 "NAME" [interpolate N]
        const Token type = r.next();
        if (!type.is(Keyword::kw_df3))
            r.fail(type, fmt::format("expected 'df3' after 'density_file', found {}",
                                     describeToken(type)));
        const Token at = r.peek();
        const std::string name = r.parseString();
        const std::filesystem::path path = r.findIncludeFile(name);
        if (path.empty()) r.fail(at, fmt::format("Cannot open file '{}'.", name));
        r.checkReadable(path, name, at);
        try {
            pattern.density =
                std::make_shared<const scene::DensityFile>(scene::DensityFile::read(path));
        } catch (const std::runtime_error& e) {
            r.fail(at, e.what());
        }
        // Its `interpolate` is a modifier (parsePatternModifier).
    } else if (kind == scene::PatternKind::PigmentPattern) {
        r.expect(Sym::LBrace, "'{' after 'pigment_pattern'");
        auto inner = std::make_shared<scene::Pigment>(*c.defaultTexture.pigment);
        parsePigmentBody(c, *inner, Sym::RBrace);
        r.expect(Sym::RBrace, "'}' closing 'pigment_pattern'");
        pattern.pigment = std::move(inner);
    } else if (kind == scene::PatternKind::Object) {
        // object { IDENTIFIER | OBJECT  [ENTRY_OUTSIDE, ENTRY_INSIDE] }: the
        // closing brace comes after the list entries (closeListPattern).
        r.expect(Sym::LBrace, "'{' after 'object'");
        const Token t = r.peek();
        scene::ObjectRef obj;
        if (t.isIdentifier()) {
            const Value* v = r.lookup(std::string(t.text));
            if (!v || !std::holds_alternative<ObjectPtr>(*v))
                r.fail(t, fmt::format("expected an object in the object pattern, found {}",
                                      describeToken(t)));
            r.next();
            obj = std::get<ObjectPtr>(*v)->object;
        } else {
            obj = parseObject(c).object;
        }
        pattern.object = std::move(obj);
    } else if (kind == scene::PatternKind::Marble || kind == scene::PatternKind::Wood) {
        pattern.waveType = scene::WaveType::Triangle;  // their default wave
    }
}

// pavement's number_of_sides, number_of_tiles, pattern, exterior, interior
// and form (after the keyword's token is peeked). Values are truncated and
// checked like povray's; only single-cell tiles are implemented.
static void parsePavementItem(BuildContext& c, scene::PavementSettings& s) {
    Reader& r = c.reader;
    const Token item = r.next();
    const Token at = r.peek();
    const int v = static_cast<int>(r.parseFloat());
    switch (item.kw) {
        case Keyword::kw_number_of_sides:
            if (v != 3 && v != 4 && v != 6)
                r.fail(at, "number_of_sides of pavement must be 3, 4 or 6.");
            s.sides = v;
            break;
        case Keyword::kw_number_of_tiles:
            if (v < 1 || v > (s.sides == 6 ? 5 : 6))
                r.fail(at, fmt::format("number_of_tiles of pavement must be between 1 and {}.",
                                       s.sides == 6 ? 5 : 6));
            // Single cells, and square dominoes (the sides may follow;
            // checkPavement looks again at the end of the pattern).
            if (v > 3) r.unsupported(at, fmt::format("pavement number_of_tiles {}", v));
            s.tiles = v;
            break;
        case Keyword::kw_pattern:
            if (v < 1) r.fail(at, "pattern value for pavement is out of range.");
            s.pattern = v;  // checked against the tile count in checkPavement
            break;
        case Keyword::kw_exterior:
            // Measured: values other than 1 and 2 act as 0.
            s.exterior = (v == 1 || v == 2) ? v : 0;
            break;
        case Keyword::kw_interior:
            s.interior = v;
            break;
        default:  // form
            // Measured: for squares and triangles, and values other than 1
            // and 2, form changes nothing in single cells and dominoes.
            s.form = v;
            break;
    }
}

// Settings checked once the whole pavement is known (they may come in any
// order): dominoes for squares only, corner shapes not built for the others.
static void checkPavement(BuildContext& c, const scene::Pattern& pattern, const Token& at) {
    Reader& r = c.reader;
    if (pattern.kind != scene::PatternKind::Pavement) return;
    const scene::PavementSettings& s = pattern.pavement;
    // povray's pattern counts per number_of_tiles (from its messages).
    static constexpr int kPatterns3[] = {1, 1, 1, 3, 4, 12};
    static constexpr int kPatterns4[] = {1, 1, 2, 5, 12, 35};
    static constexpr int kPatterns6[] = {1, 1, 3, 7, 22};
    const int* counts = s.sides == 3 ? kPatterns3 : s.sides == 4 ? kPatterns4 : kPatterns6;
    const int tileCount = s.sides == 6 ? 5 : 6;
    if (s.tiles >= 1 && s.tiles <= tileCount && s.pattern > counts[s.tiles - 1]) {
        std::string list;
        for (int i = 0; i < tileCount; ++i) {
            if (i > 0) list.push_back(',');
            list.append(std::to_string(counts[i]));
        }
        r.fail(at,
               fmt::format("pattern value for pavement is out of range. max per tile:({})", list));
    }
    // interior 1 and 2 reshape the hexagon pairs' inner corners (measured;
    // not built).
    // Three cells: only the straight squares tromino (pattern 1) with sharp
    // corners.
    if (s.tiles == 3 && (s.sides != 4 || s.pattern != 1 || s.exterior != 0))
        r.unsupported(
            at, fmt::format("pavement number_of_tiles 3 with {} sides, pattern {}, exterior {}",
                            s.sides, s.pattern, s.exterior));
    if (s.tiles == 2 && s.sides == 6 && (s.interior == 1 || s.interior == 2))
        r.unsupported(at, fmt::format("pavement interior {} with 6 sides and 2 tiles", s.interior));
    // form 1 and 2 reshape the lozenges' corners (measured; not built).
    if (s.tiles == 2 && s.sides == 3 && (s.form == 1 || s.form == 2))
        r.unsupported(at, fmt::format("pavement form {} with 3 sides and 2 tiles", s.form));
    if (s.exterior != 0 && s.sides != 4)
        r.unsupported(at, fmt::format("pavement exterior {} with {} sides", s.exterior, s.sides));
    // form 1 and 2 reshape the hexagons' corners (measured; not built).
    if (s.sides == 6 && (s.form == 1 || s.form == 2))
        r.unsupported(at, fmt::format("pavement form {} with 6 sides", s.form));
}

// slope <S> | slope { <S> [, LO, HI] [altitude <A> [, LO, HI]] }
static void parseSlopeArguments(BuildContext& c, scene::Pattern& pattern) {
    Reader& r = c.reader;
    pattern.altitudeDirection = Vec3(0, 0, 0);
    pattern.slopeLow = 0;
    pattern.slopeHigh = 1;
    pattern.altitudeLow = 0;
    pattern.altitudeHigh = 1;
    if (!r.accept(Sym::LBrace)) {
        pattern.slopeDirection = r.parseVec3();
        return;
    }
    auto range = [&](double& lo, double& hi) {
        if (!r.accept(Sym::Comma)) return;
        lo = r.parseFloat();
        r.accept(Sym::Comma);
        hi = r.parseFloat();
    };
    pattern.slopeDirection = r.parseVec3();
    range(pattern.slopeLow, pattern.slopeHigh);
    if (r.accept(Keyword::kw_altitude)) {
        pattern.altitudeDirection = r.parseVec3();
        range(pattern.altitudeLow, pattern.altitudeHigh);
    }
    const Token t = r.peek();
    if (t.kind == TokenKind::Word && t.kw != Keyword::None)
        r.unsupported(t, fmt::format("'{}' in slope", t.text));
    r.expect(Sym::RBrace, "'}' closing 'slope'");
}

void closeListPattern(BuildContext& c, const scene::Pattern& pattern) {
    Reader& r = c.reader;
    if (pattern.kind == scene::PatternKind::Object) r.expect(Sym::RBrace, "'}' closing 'object'");
}

bool parsePigmentPatternItem(BuildContext& c, scene::Pigment& pigment) {
    Reader& r = c.reader;
    const Token item = r.peek();
    if (parseImagePigmentItem(c, pigment)) return true;
    if (const auto kind = patternKeyword(item.kw)) {
        scene::Pattern pattern = pigment.pattern();
        parsePatternKeyword(c, pattern);
        pigment.setPattern(pattern);
        if (pigment.pattern().isList()) {
            // Up to listSize colours or pigments, optionally comma-separated;
            // missing ones keep the pattern's defaults.
            const std::vector<Color> defaults = defaultListColors(*kind);
            std::vector<PigmentPtr> list;
            for (const Color& colour : defaults)
                list.push_back(std::make_shared<const scene::Pigment>(colour));
            // The object pattern takes colours, or pigment { } blocks when
            // its first entry is one (the example advanced/abyss.pov), never
            // a mix nor a bare pigment identifier (measured).
            bool objectPigments = false;
            for (std::size_t i = 0; i < defaults.size(); ++i) {
                if (i > 0) r.accept(Sym::Comma);
                const Token n = r.peek();
                const bool isPigmentId =
                    n.isIdentifier() && r.lookup(std::string(n.text)) &&
                    std::holds_alternative<PigmentPtr>(*r.lookup(std::string(n.text)));
                if (!(n.is(Keyword::kw_pigment) || isPigmentId || startsColor(n))) break;
                if (*kind == scene::PatternKind::Object) {
                    if (i == 0) objectPigments = n.is(Keyword::kw_pigment);
                    if (isPigmentId || n.is(Keyword::kw_pigment) != objectPigments)
                        r.fail(n, fmt::format("No matching }} in 'object', {} found instead",
                                              describeToken(n)));
                }
                list[i] = parsePigmentListEntry(c);
            }
            pigment.setList(std::move(list));
            closeListPattern(c, pigment.pattern());
        }
        return true;
    }
    switch (item.kw) {
        case Keyword::kw_color_map:
        case Keyword::kw_colour_map:
            pigment.setColorMap(parseColorMap(c));
            return true;
        case Keyword::kw_pigment_map:
            pigment.setPigmentMap(parsePigmentMap(c));
            return true;
        case Keyword::kw_average:
            r.next();
            pigment.setAverage();
            return true;
        default: {
            if (pigment.hasPatternPart()) return parsePatternModifier(c, pigment.pattern());
            // A plain colour gets its pattern part only when a modifier is
            // there to set (issue 23: 56-byte plain pigments).
            scene::Pattern pattern = std::as_const(pigment).pattern();
            if (!parsePatternModifier(c, pattern)) return false;
            pigment.pattern() = std::move(pattern);
            return true;
        }
    }
}

bool parsePatternModifier(BuildContext& c, scene::Pattern& pattern) {
    Reader& r = c.reader;
    const Token item = r.peek();
    if (const auto wave = waveKeyword(item.kw)) {
        r.next();
        pattern.waveType = *wave;
        return true;
    }
    switch (item.kw) {
        case Keyword::kw_interpolate: {
            // density_file's, anywhere among the modifiers (the example
            // textures/patterns/densfile.pov writes it after a bump size).
            if (pattern.kind != scene::PatternKind::DensityFile) return false;
            r.next();
            const Token n = r.peek();
            const double mode = r.parseFloat();
            if (mode < 0 || mode > 2)
                r.fail(n,
                       fmt::format("density_file interpolate must be 0, 1 or 2, found {}", mode));
            pattern.densityInterpolation = static_cast<int>(mode);
            return true;
        }
        case Keyword::kw_brick_size:
            r.next();
            pattern.brickSize = r.parseVec3();
            return true;
        case Keyword::kw_mortar:
            r.next();
            pattern.mortar = r.parseFloat();
            return true;
        case Keyword::kw_control0:
            r.next();
            pattern.control0 = static_cast<float>(r.parseFloat());
            return true;
        case Keyword::kw_control1:
            r.next();
            pattern.control1 = static_cast<float>(r.parseFloat());
            return true;
        case Keyword::kw_frequency:
            r.next();
            pattern.frequency = static_cast<float>(r.parseFloat());
            return true;
        case Keyword::kw_phase:
            r.next();
            pattern.phase = static_cast<float>(r.parseFloat());
            return true;
        case Keyword::kw_poly_wave: {
            r.next();
            const double e = r.parseOptionalFloat(1.0);
            pattern.waveType = scene::WaveType::Poly;
            pattern.exponent = e;
            return true;
        }
        case Keyword::kw_number_of_sides:
        case Keyword::kw_number_of_tiles:
        case Keyword::kw_pattern:
        case Keyword::kw_exponent:
        case Keyword::kw_interior:
        case Keyword::kw_exterior:
        case Keyword::kw_form:
            return parsePatternSetting(c, pattern);
        case Keyword::kw_metric:
            r.next();
            pattern.crackle.metric = r.parseFloat();
            return true;
        case Keyword::kw_offset:
            r.next();
            pattern.crackle.offset = r.parseFloat();
            return true;
        case Keyword::kw_solid:
            r.next();
            pattern.crackle.solid = true;
            return true;
        case Keyword::kw_coords:
        case Keyword::kw_size:
            // coords C tilts by C (the cell size stays `size`); measured:
            // the coords value does not scale the cells.
            if (pattern.kind != scene::PatternKind::Facets) return false;
            r.next();
            if (item.is(Keyword::kw_coords))
                pattern.facets.coords = r.parseFloat();
            else
                pattern.facets.size = r.parseFloat();
            return true;
        case Keyword::kw_agate_turb:
            r.next();
            pattern.agateTurb = r.parseFloat();
            return true;
        case Keyword::kw_noise_generator:
            r.next();
            pattern.noiseGenerator = parseNoiseGenerator(c, item);
            pattern.noiseGeneratorGiven = true;
            return true;
        case Keyword::kw_warp:
            r.next();
            pattern.addWarp(parseWarp(c));
            return true;
        default: {
            scene::Turbulence turb = pattern.turbulence.value_or(scene::Turbulence{});
            if (!parseTurbulenceItem(c, turb)) return false;
            pattern.turbulence = turb;
            return true;
        }
    }
}

// The modifiers whose meaning depends on the pattern kind: pavement's
// settings, the fractals' exponent, interior and exterior, and form
// (pavement's or crackle's).
static bool parsePatternSetting(BuildContext& c, scene::Pattern& pattern) {
    Reader& r = c.reader;
    const Token item = r.peek();
    const bool pavement = pattern.kind == scene::PatternKind::Pavement;
    if (pavement && !item.is(Keyword::kw_exponent)) {
        parsePavementItem(c, pattern.pavement);
        return true;
    }
    if (item.is(Keyword::kw_form)) {
        r.next();
        pattern.crackle.form = r.parseVec3();
        return true;
    }
    if (pattern.kind != scene::PatternKind::Fractal || item.is(Keyword::kw_number_of_sides) ||
        item.is(Keyword::kw_number_of_tiles) || item.is(Keyword::kw_pattern))
        return false;
    r.next();
    parseFractalItem(c, item, pattern.fractal);
    return true;
}

std::shared_ptr<const scene::Normal> parseNormal(BuildContext& c, const scene::Normal* base,
                                                 scene::Normal* settings) {
    Reader& r = c.reader;
    r.next();  // normal
    r.expect(Sym::LBrace, "'{' after 'normal'");
    auto normal = parseNormalBody(c, base, Sym::RBrace, settings);
    r.expect(Sym::RBrace, "'}' closing 'normal'");
    return normal;
}

std::shared_ptr<const scene::Normal> parseNormalBody(BuildContext& c, const scene::Normal* base,
                                                     Sym closing, scene::Normal* settings) {
    Reader& r = c.reader;
    const Reader::NestingGuard nesting(r, r.peek());
    scene::Normal normal = base ? *base : c.defaultNormal;
    bool havePattern = base != nullptr;
    // A declared normal to start from.
    if (const Token first = r.peek(); first.isIdentifier()) {
        const Value* v = r.lookup(std::string(first.text));
        // A normal identifier, or an element of an array of normals.
        if (v && (std::holds_alternative<NormalPtr>(*v) || arrayHolds<NormalPtr>(*v))) {
            r.next();
            const Value value = r.identifierValue(first, v);
            const auto* declared = std::get_if<NormalPtr>(&value);
            if (!declared)
                r.fail(first, fmt::format("expected a normal, found a {}", valueKindName(value)));
            normal = *declared ? **declared : scene::Normal{};
            havePattern = *declared != nullptr;
        }
    }
    // As in a pigment: transformations after a uv-mapped identifier do
    // nothing (measured).
    const bool uvFrozen = normal.uvMapping && havePattern;
    if (r.accept(Keyword::kw_uv_mapping)) normal.uvMapping = true;
    // The pattern with its chain of transformations and warps.
    scene::Pattern& pattern = normal.pattern;
    // An optional bump size follows the pattern, after an optional comma
    // (povray: `gradient x, 5.6`; the fractals write it so).
    auto parseBumpSize = [&] {
        r.accept(Sym::Comma);
        if (r.floatFollows()) normal.amount = r.parseFloat();
    };
    while (!r.peek().is(closing)) {
        const Token item = r.peek();
        Transform step;
        if (r.parseTransformation(step)) {
            if (uvFrozen) continue;
            pattern.addTransform(step);
            // The normals of a map move with it (as a texture map's do).
            for (auto& e : normal.map) {
                if (!e.normal) continue;
                auto moved = std::make_shared<scene::Normal>(*e.normal);
                moved->transformBy(step);
                e.normal = std::move(moved);
            }
            continue;
        }
        if (patternKeyword(item.kw)) {
            parsePatternKeyword(c, pattern, true);
            havePattern = true;
            if (pattern.isList() && !r.peek().is(Keyword::kw_normal)) {
                // A list pattern without normals is a bumpy pattern of its
                // own: its index is sampled, so only the cells' edges tilt.
                closeListPattern(c, pattern);
                if (normal.mapMode == scene::Normal::MapMode::List)
                    normal.mapMode = scene::Normal::MapMode::None;
                parseBumpSize();
                continue;
            }
            if (pattern.isList()) {
                // A list pattern takes one normal per index.
                normal.mapMode = scene::Normal::MapMode::List;
                normal.map.clear();
                const int count = scene::Pattern::listSize(pattern.kind);
                for (int i = 0; i < count; ++i) {
                    if (i > 0) r.accept(Sym::Comma);
                    if (!r.peek().is(Keyword::kw_normal)) break;
                    const Token entryAt = r.peek();
                    auto entry = parseNormal(c, nullptr);
                    if (entry && entry->uvMapping)
                        r.unsupported(entryAt, "uv_mapping in a normal of a list pattern");
                    normal.map.push_back({static_cast<double>(i), std::move(entry)});
                }
                while (static_cast<int>(normal.map.size()) < count)
                    normal.map.push_back({static_cast<double>(normal.map.size()), nullptr});
                closeListPattern(c, pattern);
                continue;
            }
            if (normal.mapMode == scene::Normal::MapMode::List)
                normal.mapMode = scene::Normal::MapMode::None;
            parseBumpSize();
            continue;
        }
        switch (item.kw) {
            case Keyword::kw_bump_size:
                r.next();
                normal.amount = r.parseFloat();
                continue;
            case Keyword::kw_accuracy:
                r.next();
                normal.accuracy = r.parseFloat();
                continue;
            case Keyword::kw_normal_map:
                if (normal.mapMode == scene::Normal::MapMode::List)
                    r.fail(item, "a list pattern takes normals, not a normal_map");
                normal.map = parseNormalMap(c);
                if (normal.mapMode == scene::Normal::MapMode::None)
                    normal.mapMode = scene::Normal::MapMode::Values;
                continue;
            case Keyword::kw_slope_map:
                normal.slopeMap = parseSlopeMap(c);
                continue;
            case Keyword::kw_average:
                r.next();
                normal.mapMode = scene::Normal::MapMode::Average;
                havePattern = true;
                continue;
            case Keyword::kw_color_map:
            case Keyword::kw_colour_map:
            case Keyword::kw_pigment_map:
            case Keyword::kw_image_map:  // povray: only in a pigment
                r.fail(item, fmt::format("'{}' is not allowed in a normal", item.text));
            default:
                break;
        }
        if (parseImageNormalItem(c, normal, pattern)) {
            havePattern = true;
            continue;
        }
        if (parsePatternModifier(c, pattern)) continue;
        if (item.kind == TokenKind::Word && item.kw != Keyword::None)
            r.unsupported(item, fmt::format("'{}' in normal", item.text));
        r.fail(item, fmt::format("expected a normal item or '{}', found {}",
                                 closing == Sym::RBrace ? "}" : "]", describeToken(item)));
    }
    checkPavement(c, normal.pattern, r.peek());
    if (settings) *settings = normal;
    if (!havePattern) return nullptr;  // normal { } without a pattern: no perturbation
    return std::make_shared<const scene::Normal>(normal);
}

// mandel ITERATIONS | julia <C>, ITERATIONS | magnet 1|2 (mandel | julia <C>,)
// ITERATIONS
static void parseFractalHead(BuildContext& c, const Token& kind, scene::FractalSettings& f) {
    Reader& r = c.reader;
    using Kind = scene::FractalSettings::Kind;
    f = scene::FractalSettings{};
    Token form = kind;
    int magnetType = 0;
    if (kind.is(Keyword::kw_magnet)) {
        const Token at = r.peek();
        const double t = r.parseFloat();
        if (t != 1 && t != 2) r.fail(at, fmt::format("magnet type must be 1 or 2, found {}", t));
        magnetType = static_cast<int>(t);
        form = r.next();
        if (!form.is(Keyword::kw_mandel) && !form.is(Keyword::kw_julia))
            r.fail(form, fmt::format("expected 'mandel' or 'julia' after 'magnet {}', found {}",
                                     magnetType, describeToken(form)));
    }
    const bool julia = form.is(Keyword::kw_julia);
    f.kind = magnetType == 0   ? (julia ? Kind::Julia : Kind::Mandel)
             : magnetType == 1 ? (julia ? Kind::Magnet1Julia : Kind::Magnet1Mandel)
                               : (julia ? Kind::Magnet2Julia : Kind::Magnet2Mandel);
    if (julia) {
        const VectorValue constant = r.parseVector();
        f.cx = constant.v[0];
        f.cy = constant.v[1];
        r.accept(Sym::Comma);
    }
    const Token at = r.peek();
    const double n = r.parseFloat();
    if (n < 1) r.fail(at, fmt::format("{} needs at least one iteration, found {}", kind.text, n));
    f.iterations = static_cast<int>(n);
}

// exponent N | interior TYPE, FACTOR | exterior TYPE, FACTOR (after the
// keyword). povray rejects the same values (types outside 0..6, exponent
// on a magnet).
static void parseFractalItem(BuildContext& c, const Token& item, scene::FractalSettings& f) {
    Reader& r = c.reader;
    if (item.is(Keyword::kw_exponent)) {
        if (f.isMagnet()) r.fail(item, "'exponent' can only be used with mandel or julia");
        const Token at = r.peek();
        const double e = r.parseFloat();
        if (e < 2 || e > 33 || e != std::floor(e))
            r.fail(at, fmt::format("fractal exponent must be a whole number from 2 to 33, found {}",
                                   e));
        f.exponent = static_cast<int>(e);
        return;
    }
    const Token at = r.peek();
    const double typeValue = r.parseFloat();
    r.accept(Sym::Comma);
    const double factor = r.parseFloat();
    const int type = static_cast<int>(typeValue);  // truncated like povray's
    if (type < 0 || type > 6)
        r.fail(at, fmt::format("fractal {} type must be 0 to 6, found {}", item.text, typeValue));
    if (item.is(Keyword::kw_interior)) {
        f.interiorType = type;
        f.interiorFactor = factor;
    } else {
        f.exteriorType = type;
        f.exteriorFactor = factor;
    }
}

scene::NoiseGenerator parseNoiseGenerator(BuildContext& c, const Token& at) {
    Reader& r = c.reader;
    const double g = r.parseFloat();
    if (g == 1) return scene::NoiseGenerator::Original;
    if (g == 2) return scene::NoiseGenerator::RangeCorrected;
    if (g == 3) return scene::NoiseGenerator::Perlin;
    r.fail(at, fmt::format("noise_generator must be 1, 2 or 3, found {}", g));
}

bool parseTurbulenceItem(BuildContext& c, scene::Turbulence& turb) {
    Reader& r = c.reader;
    const Token item = r.peek();
    switch (item.kw) {
        case Keyword::kw_turbulence: {
            r.next();
            turb.amount = r.parseVec3();
            return true;
        }
        case Keyword::kw_octaves: {
            r.next();
            const double o = r.parseFloat();
            // povray clamps octaves to 1..10.
            turb.octaves = std::clamp(static_cast<int>(o), 1, 10);
            return true;
        }
        case Keyword::kw_omega: {
            r.next();
            turb.omega = static_cast<float>(r.parseFloat());
            return true;
        }
        case Keyword::kw_lambda: {
            r.next();
            turb.lambda = static_cast<float>(r.parseFloat());
            return true;
        }
        default:
            return false;
    }
}

static scene::Warp parseWarp(BuildContext& c) {
    Reader& r = c.reader;
    r.expect(Sym::LBrace, "'{' after 'warp'");
    scene::Warp w;
    const Token kind = r.next();
    if (kind.is(Keyword::kw_turbulence)) {
        w.kind = scene::Warp::Kind::Turbulence;
        w.turb.amount = r.parseVec3();
        while (parseTurbulenceItem(c, w.turb)) {
        }
    } else if (kind.is(Keyword::kw_repeat)) {
        w.kind = scene::Warp::Kind::Repeat;
        const Vec3 dir = r.parseVec3();
        int axes = 0;
        for (int i = 0; i < 3; ++i)
            if (dir[i] != 0) {
                w.axis = i;
                ++axes;
            }
        if (axes != 1) r.fail(kind, "warp repeat needs a direction along one axis (x, y or z)");
        w.width = dir[w.axis];
        for (;;) {
            const Token t = r.peek();
            if (t.is(Keyword::kw_offset)) {
                r.next();
                w.offset = r.parseVec3();
            } else if (t.is(Keyword::kw_flip)) {
                r.next();
                const Vec3 f = r.parseVec3();
                for (int i = 0; i < 3; ++i) w.flip[i] = f[i] != 0;
            } else {
                break;
            }
        }
    } else if (kind.is(Keyword::kw_black_hole)) {
        w.kind = scene::Warp::Kind::BlackHole;
        w.center = r.parseVec3();
        r.accept(Sym::Comma);
        w.radius = r.parseFloat();
        for (;;) {
            const Token t = r.peek();
            if (t.is(Keyword::kw_strength)) {
                r.next();
                w.strength = r.parseFloat();
            } else if (t.is(Keyword::kw_falloff)) {
                r.next();
                w.falloff = r.parseFloat();
            } else if (t.is(Keyword::kw_inverse)) {
                r.next();
                w.inverse = true;
            } else if (t.is(Keyword::kw_repeat)) {
                r.next();
                w.repeat = r.parseVec3();
                w.repeats = true;
            } else if (t.is(Keyword::kw_turbulence)) {
                // The jitter of each repeated hole (povray: only with repeat).
                r.next();
                w.jitter = r.parseVec3();
                w.jittered = true;
            } else {
                break;
            }
        }
        // Along a repeated axis povray keeps the hole clear of the cell's
        // lower faces: a centre closer to them than the radius moves up to
        // it (measured: <0, 0, 0>, 0.5 repeat <2, 1.5, 0> centres the holes
        // at <0.5, 0.5, 0> of each cell; the upper faces cut the hole).
        if (w.repeats)
            for (int i = 0; i < 3; ++i)
                if (w.repeat[i] >= 1e-10 && w.center[i] < w.radius) w.center[i] = w.radius;
    } else if (kind.is(Keyword::kw_cylindrical) || kind.is(Keyword::kw_spherical) ||
               kind.is(Keyword::kw_toroidal)) {
        // cylindrical | spherical | toroidal [orientation V] [dist_exp E]
        // [major_radius R] (toroidal only; povray rejects it elsewhere).
        w.kind = kind.is(Keyword::kw_cylindrical) ? scene::Warp::Kind::Cylindrical
                 : kind.is(Keyword::kw_spherical) ? scene::Warp::Kind::Spherical
                                                  : scene::Warp::Kind::Toroidal;
        for (;;) {
            const Token t = r.peek();
            if (t.is(Keyword::kw_orientation)) {
                r.next();
                const Vec3 o = r.parseVec3();
                // povray normalises it (a zero vector gives NaN there).
                if (length(o) == 0) r.fail(t, "warp orientation vector is zero");
                w.orientation = normalize(o);
            } else if (t.is(Keyword::kw_dist_exp)) {
                r.next();
                w.distExp = r.parseFloat();
            } else if (t.is(Keyword::kw_major_radius) && w.kind == scene::Warp::Kind::Toroidal) {
                r.next();
                w.majorRadius = r.parseFloat();
            } else {
                break;
            }
        }
    } else if (kind.is(Keyword::kw_planar)) {
        // planar [NORMAL, DISTANCE]: the distance is required after a normal.
        w.kind = scene::Warp::Kind::Planar;
        if (!r.peek().is(Sym::RBrace)) {
            const Token at = r.peek();
            const Vec3 o = r.parseVec3();
            if (length(o) == 0) r.fail(at, "warp planar normal is zero");
            w.orientation = normalize(o);
            r.accept(Sym::Comma);
            w.planeDistance = r.parseFloat();
        }
    } else if (kind.kind == TokenKind::Word && kind.kw != Keyword::None) {
        r.unsupported(kind, fmt::format("warp {{ {} }}", kind.text));
    } else {
        r.fail(kind, fmt::format("expected a warp type in 'warp', found {}", describeToken(kind)));
    }
    r.expect(Sym::RBrace, "'}' after a warp");
    return w;
}

scene::ColorMap parseColorMap(BuildContext& c) {
    Reader& r = c.reader;
    const Token kw = r.next();  // color_map
    r.expect(Sym::LBrace, "'{' after 'color_map'");
    if (const BlendMapValue* m = blendMapIdentifier(c, BlendMapValue::Kind::Color)) {
        r.expect(Sym::RBrace, "'}' after a color_map identifier");
        return m->colors;
    }
    std::vector<scene::ColorMap::Entry> entries;
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        const Token open = r.peek();
        r.expect(Sym::LBracket, "'[' or '}' in color_map");
        const double v1 = parseMapValue(c);
        r.accept(Sym::Comma);
        if (r.peek().kind == TokenKind::Number) {
            // [v1, v2 color C1 color C2] or, without the comma, [v1 v2 color
            // C1 color C2] (woodmaps.inc, stars.inc): a band from C1 to C2.
            // povray wants 'color' before a colour here, so a number after
            // the first value always starts the second.
            const double v2 = r.parseFloat();
            const Color c1 = r.parseColor();
            const Color c2 = r.parseColor();
            entries.push_back({v1, c1});
            entries.push_back({v2, c2});
        } else {
            entries.push_back({v1, r.parseColor()});
        }
        r.expect(Sym::RBracket, "']' after a color_map entry");
        if (entries.size() > scene::ColorMap::kMaxEntries)
            r.fail(open, fmt::format("a color_map holds at most {} entries",
                                     scene::ColorMap::kMaxEntries));
    }
    if (entries.empty()) r.fail(kw, "color_map needs at least one entry");
    // Entries out of order are kept as written: povray accepts them
    // (woods.inc T_Wood32 has [0.95 ..] [0.90 ..]) and ColorMap::at scans
    // them in order as povray does.
    return scene::ColorMap(std::move(entries));
}

std::vector<scene::Pigment::MapEntry> parsePigmentMap(BuildContext& c) {
    Reader& r = c.reader;
    const Token kw = r.next();  // pigment_map
    r.expect(Sym::LBrace, "'{' after 'pigment_map'");
    if (const BlendMapValue* m = blendMapIdentifier(c, BlendMapValue::Kind::Pigment)) {
        r.expect(Sym::RBrace, "'}' after a pigment_map identifier");
        return m->pigments;
    }
    std::vector<scene::Pigment::MapEntry> entries;
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        r.expect(Sym::LBracket, "'[' or '}' in pigment_map");
        const double v = parseMapValue(c, true);
        r.accept(Sym::Comma);
        // [v PIGMENT_BODY]: a colour, a pigment identifier, a pattern...
        auto entry = std::make_shared<scene::Pigment>();
        parsePigmentBody(c, *entry, Sym::RBracket);
        entries.push_back({v, std::move(entry)});
        r.expect(Sym::RBracket, "']' after a pigment_map entry");
    }
    if (entries.empty()) r.fail(kw, "pigment_map needs at least one entry");
    if (entries.size() > scene::ColorMap::kMaxEntries)
        r.fail(kw,
               fmt::format("a pigment_map holds at most {} entries", scene::ColorMap::kMaxEntries));
    // Not checked for order: under `average` the values are weights.
    return entries;
}

// function { pattern { PATTERN MODIFIERS } }: the pattern's value at x, y, z.
Value parsePatternFunction(BuildContext& c) {
    Reader& r = c.reader;
    FunctionValue value;
    const Token at = r.next();  // pattern
    r.expect(Sym::LBrace, "'{' after 'pattern'");
    scene::Pigment holder;  // holds the pattern and its chain, as normals do
    bool havePattern = false;
    while (!r.peek().is(Sym::RBrace)) {
        const Token item = r.peek();
        Transform step;
        if (r.parseTransformation(step)) {
            holder.transform(step);
            continue;
        }
        // povray 3.7 refuses square, triangular, slope, aoi, tiling and pavement here
        // (but not cubic).
        if (item.is(Keyword::kw_square) || item.is(Keyword::kw_triangular) ||
            item.is(Keyword::kw_slope) || item.is(Keyword::kw_aoi) || item.is(Keyword::kw_tiling) ||
            item.is(Keyword::kw_pavement))
            r.fail(item, fmt::format("'{}' cannot be used in a pattern function", item.text));
        if (isPatternKeyword(item)) havePattern = true;
        if (parsePigmentPatternItem(c, holder)) continue;
        if (item.kind == TokenKind::Word && item.kw != Keyword::None) {
            // functions.inc declares pattern functions for every pattern:
            // declaring one frameray lacks is fine, using it is not.
            value.unsupported = fmt::format("'{}' in a pattern function", item.text);
            r.skipToClosingBrace(at, 2);
            return FunctionPtr(std::make_shared<FunctionValue>(value));
        }
        r.fail(item, fmt::format("expected a pattern or '}}', found {}", describeToken(item)));
    }
    r.next();  // }
    r.expect(Sym::RBrace, "'}' closing the function body");
    if (!havePattern) r.fail(at, "a pattern function needs a pattern");
    value.compiled = nativeBody("pattern function", 3,
                                std::make_shared<scene::PatternFunction>(holder.pattern()));
    return FunctionPtr(std::make_shared<FunctionValue>(value));
}

}  // namespace frameray::sdl
