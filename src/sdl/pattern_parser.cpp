// Pigments and their patterns: pigment { }, colour lists, colour and
// pigment maps, pattern modifiers, turbulence and warps (seed 003 §5.4.1).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include "sdl/interpreter.h"

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

}  // namespace

PigmentPtr Interpreter::parsePigment(const scene::Pigment* base) {
    next();  // pigment
    expect(Sym::LBrace, "'{' after 'pigment'");
    // povray edits the pigment a texture already has (measured:
    // texture { T pigment { scale 0.3 } } scales T's checker).
    auto result = std::make_shared<scene::Pigment>(base ? *base : *defaultTexture_.pigment);
    parsePigmentBody(*result, Sym::RBrace);
    expect(Sym::RBrace, "'}' closing 'pigment'");
    return result;
}

void Interpreter::parsePigmentBody(scene::Pigment& result, Sym closing) {
    const Token t = peek();
    const NestingGuard nesting(*this, t);
    // uv_mapping (povray 3.7, measured): first in the block, maybe followed
    // by an identifier; the block's transformations then move the uv
    // pattern, while those after a uv-mapped identifier do nothing.
    bool uvFrozen = false;
    auto copyIdentifier = [&] {
        const Token id = peek();
        if (!id.isIdentifier()) return false;
        const Value* v = lookup(std::string(id.text));
        // A pigment identifier, or an element of an array of pigments
        // (`pigment { Pigments[I] }`, the example portfolio).
        if (!v || !(std::holds_alternative<PigmentPtr>(*v) || arrayHolds<PigmentPtr>(*v)))
            return false;
        next();
        const Value declared = identifierValue(id, v);
        const auto* pigment = std::get_if<PigmentPtr>(&declared);
        if (!pigment)
            fail(id, fmt::format("expected a pigment, found a {}", valueKindName(declared)));
        result = **pigment;
        return true;
    };
    if (copyIdentifier()) {
        uvFrozen = result.uvMapping();
        if (peek().is(Keyword::kw_uv_mapping))
            unsupported(peek(), "uv_mapping after a pigment identifier");
    } else if (accept(Keyword::kw_uv_mapping)) {
        copyIdentifier();
        result.setUvMapping();
    }
    while (!peek().is(closing)) {
        const Token item = peek();
        Transform step;
        if (parseTransformation(step)) {
            if (!uvFrozen) result.transform(step);
            continue;
        }
        if (item.is(Keyword::kw_quick_color) || item.is(Keyword::kw_quick_colour)) {
            next();
            result.setQuickColor(parseColor());
            continue;
        }
        if (item.is(Keyword::kw_uv_mapping))
            unsupported(item, "uv_mapping after other pigment items");
        if (parsePigmentPatternItem(result)) continue;
        if (startsColor(item)) {
            result.setSolid(parseColor());
            continue;
        }
        if (item.kind == TokenKind::Word && item.kw != Keyword::None)
            unsupported(item, fmt::format("'{}' in pigment", item.text));
        fail(item, fmt::format("expected a color or pigment item, found {}", describeToken(item)));
    }
    checkPavement(result.pattern(), peek());
    result.settleDefaultColorMap();
}

PigmentPtr Interpreter::parsePigmentListEntry() {
    const Token t = peek();
    if (t.is(Keyword::kw_pigment)) return parsePigment();
    if (t.isIdentifier()) {
        const Value* v = lookup(std::string(t.text));
        if (v && std::holds_alternative<PigmentPtr>(*v)) {
            next();
            return std::get<PigmentPtr>(*v);
        }
    }
    return std::make_shared<const scene::Pigment>(parseColor());
}

bool Interpreter::isPatternKeyword(const Token& t) const {
    return patternKeyword(t.kw).has_value();
}

void Interpreter::parsePatternKeyword(scene::Pigment& pigment, bool inNormal) {
    const Token item = next();
    const scene::PatternKind kind = *patternKeyword(item.kw);
    if (kind == scene::PatternKind::Facets && !inNormal)
        fail(item, "'facets' can only be used in a normal");
    scene::Pattern pattern = pigment.pattern();
    pattern.kind = kind;
    if (kind == scene::PatternKind::Gradient) {
        const Vec3 g = parseVec3();
        const double len = length(g);
        if (len == 0) fail(item, "gradient vector is zero");
        pattern.gradient = g * (1.0 / len);
    } else if (kind == scene::PatternKind::Spiral1 || kind == scene::PatternKind::Spiral2) {
        // The number of arms is truncated to a whole number (measured);
        // spirals default to the triangle wave like marble and wood.
        pattern.arms = static_cast<int>(parseFloat());
        pattern.waveType = scene::WaveType::Triangle;
    } else if (kind == scene::PatternKind::Fractal) {
        parseFractalHead(item, pattern.fractal);
    } else if (kind == scene::PatternKind::Function) {
        pattern.function = parseXyzFunction(item);
    } else if (kind == scene::PatternKind::Slope) {
        parseSlopeArguments(pattern);
    } else if (kind == scene::PatternKind::Tiling) {
        // tiling N: truncated like povray's other counts (measured: 1.9 is 1).
        const Token at = peek();
        const double n = parseFloat();
        const int number = static_cast<int>(n);
        if (number < 1 || number > 27) fail(at, "Tiling number must be between 1 and 27.");
        if (!scene::tilingSupported(number)) unsupported(at, fmt::format("tiling {}", number));
        pattern.tiling = number;
    } else if (kind == scene::PatternKind::DensityFile) {
        // density_file df3 "NAME" [interpolate N]
        const Token type = next();
        if (!type.is(Keyword::kw_df3))
            fail(type,
                 fmt::format("expected 'df3' after 'density_file', found {}", describeToken(type)));
        const Token at = peek();
        const std::string name = parseString();
        const std::filesystem::path path = findIncludeFile(name);
        if (path.empty()) fail(at, fmt::format("Cannot open file '{}'.", name));
        checkReadable(path, name, at);
        try {
            pattern.density =
                std::make_shared<const scene::DensityFile>(scene::DensityFile::read(path));
        } catch (const std::runtime_error& e) {
            fail(at, e.what());
        }
        // Its `interpolate` is a modifier (parsePigmentPatternItem).
    } else if (kind == scene::PatternKind::PigmentPattern) {
        expect(Sym::LBrace, "'{' after 'pigment_pattern'");
        auto inner = std::make_shared<scene::Pigment>(*defaultTexture_.pigment);
        parsePigmentBody(*inner, Sym::RBrace);
        expect(Sym::RBrace, "'}' closing 'pigment_pattern'");
        pattern.pigment = std::move(inner);
    } else if (kind == scene::PatternKind::Object) {
        // object { IDENTIFIER | OBJECT  [ENTRY_OUTSIDE, ENTRY_INSIDE] }: the
        // closing brace comes after the list entries (closeListPattern).
        expect(Sym::LBrace, "'{' after 'object'");
        const Token t = peek();
        scene::ObjectRef obj;
        if (t.isIdentifier()) {
            const Value* v = lookup(std::string(t.text));
            if (!v || !std::holds_alternative<ObjectPtr>(*v))
                fail(t, fmt::format("expected an object in the object pattern, found {}",
                                    describeToken(t)));
            next();
            obj = std::get<ObjectPtr>(*v)->object;
        } else {
            obj = parseObject().object;
        }
        pattern.object = std::move(obj);
    } else if (kind == scene::PatternKind::Marble || kind == scene::PatternKind::Wood) {
        pattern.waveType = scene::WaveType::Triangle;  // their default wave
    }
    pigment.setPattern(pattern);
}

// pavement's number_of_sides, number_of_tiles, pattern, exterior, interior
// and form (after the keyword's token is peeked). Values are truncated and
// checked like povray's; only single-cell tiles are implemented.
void Interpreter::parsePavementItem(scene::PavementSettings& s) {
    const Token item = next();
    const Token at = peek();
    const int v = static_cast<int>(parseFloat());
    switch (item.kw) {
        case Keyword::kw_number_of_sides:
            if (v != 3 && v != 4 && v != 6)
                fail(at, "number_of_sides of pavement must be 3, 4 or 6.");
            s.sides = v;
            break;
        case Keyword::kw_number_of_tiles:
            if (v < 1 || v > (s.sides == 6 ? 5 : 6))
                fail(at, fmt::format("number_of_tiles of pavement must be between 1 and {}.",
                                     s.sides == 6 ? 5 : 6));
            // Single cells, and square dominoes (the sides may follow;
            // checkPavement looks again at the end of the pattern).
            if (v > 3) unsupported(at, fmt::format("pavement number_of_tiles {}", v));
            s.tiles = v;
            break;
        case Keyword::kw_pattern:
            if (v < 1) fail(at, "pattern value for pavement is out of range.");
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
void Interpreter::checkPavement(const scene::Pattern& pattern, const Token& at) {
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
        fail(at,
             fmt::format("pattern value for pavement is out of range. max per tile:({})", list));
    }
    // interior 1 and 2 reshape the hexagon pairs' inner corners (measured;
    // not built).
    // Three cells: only the straight squares tromino (pattern 1) with sharp
    // corners.
    if (s.tiles == 3 && (s.sides != 4 || s.pattern != 1 || s.exterior != 0))
        unsupported(at,
                    fmt::format("pavement number_of_tiles 3 with {} sides, pattern {}, exterior {}",
                                s.sides, s.pattern, s.exterior));
    if (s.tiles == 2 && s.sides == 6 && (s.interior == 1 || s.interior == 2))
        unsupported(at, fmt::format("pavement interior {} with 6 sides and 2 tiles", s.interior));
    // form 1 and 2 reshape the lozenges' corners (measured; not built).
    if (s.tiles == 2 && s.sides == 3 && (s.form == 1 || s.form == 2))
        unsupported(at, fmt::format("pavement form {} with 3 sides and 2 tiles", s.form));
    if (s.exterior != 0 && s.sides != 4)
        unsupported(at, fmt::format("pavement exterior {} with {} sides", s.exterior, s.sides));
    // form 1 and 2 reshape the hexagons' corners (measured; not built).
    if (s.sides == 6 && (s.form == 1 || s.form == 2))
        unsupported(at, fmt::format("pavement form {} with 6 sides", s.form));
}

// slope <S> | slope { <S> [, LO, HI] [altitude <A> [, LO, HI]] }
void Interpreter::parseSlopeArguments(scene::Pattern& pattern) {
    pattern.altitudeDirection = Vec3(0, 0, 0);
    pattern.slopeLow = 0;
    pattern.slopeHigh = 1;
    pattern.altitudeLow = 0;
    pattern.altitudeHigh = 1;
    if (!accept(Sym::LBrace)) {
        pattern.slopeDirection = parseVec3();
        return;
    }
    auto range = [&](double& lo, double& hi) {
        if (!accept(Sym::Comma)) return;
        lo = parseFloat();
        accept(Sym::Comma);
        hi = parseFloat();
    };
    pattern.slopeDirection = parseVec3();
    range(pattern.slopeLow, pattern.slopeHigh);
    if (accept(Keyword::kw_altitude)) {
        pattern.altitudeDirection = parseVec3();
        range(pattern.altitudeLow, pattern.altitudeHigh);
    }
    const Token t = peek();
    if (t.kind == TokenKind::Word && t.kw != Keyword::None)
        unsupported(t, fmt::format("'{}' in slope", t.text));
    expect(Sym::RBrace, "'}' closing 'slope'");
}

void Interpreter::closeListPattern(const scene::Pattern& pattern) {
    if (pattern.kind == scene::PatternKind::Object) expect(Sym::RBrace, "'}' closing 'object'");
}

bool Interpreter::parsePigmentPatternItem(scene::Pigment& pigment) {
    const Token item = peek();
    if (parseImagePigmentItem(pigment)) return true;
    if (const auto kind = patternKeyword(item.kw)) {
        parsePatternKeyword(pigment);
        if (pigment.pattern().isList()) {
            // Up to listSize colours or pigments, optionally comma-separated;
            // missing ones keep the pattern's defaults.
            const std::vector<Color> defaults = defaultListColors(*kind);
            std::vector<PigmentPtr> list;
            for (const Color& c : defaults)
                list.push_back(std::make_shared<const scene::Pigment>(c));
            // The object pattern takes colours, or pigment { } blocks when
            // its first entry is one (the example advanced/abyss.pov), never
            // a mix nor a bare pigment identifier (measured).
            bool objectPigments = false;
            for (std::size_t i = 0; i < defaults.size(); ++i) {
                if (i > 0) accept(Sym::Comma);
                const Token n = peek();
                const bool isPigmentId =
                    n.isIdentifier() && lookup(std::string(n.text)) &&
                    std::holds_alternative<PigmentPtr>(*lookup(std::string(n.text)));
                if (!(n.is(Keyword::kw_pigment) || isPigmentId || startsColor(n))) break;
                if (*kind == scene::PatternKind::Object) {
                    if (i == 0) objectPigments = n.is(Keyword::kw_pigment);
                    if (isPigmentId || n.is(Keyword::kw_pigment) != objectPigments)
                        fail(n, fmt::format("No matching }} in 'object', {} found instead",
                                            describeToken(n)));
                }
                list[i] = parsePigmentListEntry();
            }
            pigment.setList(std::move(list));
            closeListPattern(pigment.pattern());
        }
        return true;
    }
    auto editPattern = [&](auto&& edit) {
        scene::Pattern p = pigment.pattern();
        edit(p);
        pigment.pattern() = p;
    };
    switch (item.kw) {
        case Keyword::kw_color_map:
        case Keyword::kw_colour_map:
            pigment.setColorMap(parseColorMap());
            return true;
        case Keyword::kw_pigment_map:
            pigment.setPigmentMap(parsePigmentMap());
            return true;
        case Keyword::kw_average:
            next();
            pigment.setAverage();
            return true;
        case Keyword::kw_interpolate: {
            // density_file's, anywhere among the modifiers (the example
            // textures/patterns/densfile.pov writes it after a bump size).
            if (pigment.pattern().kind != scene::PatternKind::DensityFile) return false;
            next();
            const Token n = peek();
            const double mode = parseFloat();
            if (mode < 0 || mode > 2)
                fail(n, fmt::format("density_file interpolate must be 0, 1 or 2, found {}", mode));
            editPattern(
                [&](scene::Pattern& p) { p.densityInterpolation = static_cast<int>(mode); });
            return true;
        }
        case Keyword::kw_brick_size: {
            next();
            const Vec3 v = parseVec3();
            editPattern([&](scene::Pattern& p) { p.brickSize = v; });
            return true;
        }
        case Keyword::kw_mortar: {
            next();
            const double m = parseFloat();
            editPattern([&](scene::Pattern& p) { p.mortar = m; });
            return true;
        }
        case Keyword::kw_control0: {
            next();
            const double c = parseFloat();
            editPattern([&](scene::Pattern& p) { p.control0 = static_cast<float>(c); });
            return true;
        }
        case Keyword::kw_control1: {
            next();
            const double c = parseFloat();
            editPattern([&](scene::Pattern& p) { p.control1 = static_cast<float>(c); });
            return true;
        }
        case Keyword::kw_frequency: {
            next();
            const double f = parseFloat();
            editPattern([&](scene::Pattern& p) { p.frequency = static_cast<float>(f); });
            return true;
        }
        case Keyword::kw_phase: {
            next();
            const double f = parseFloat();
            editPattern([&](scene::Pattern& p) { p.phase = static_cast<float>(f); });
            return true;
        }
        case Keyword::kw_ramp_wave:
        case Keyword::kw_triangle_wave:
        case Keyword::kw_sine_wave:
        case Keyword::kw_scallop_wave:
        case Keyword::kw_cubic_wave: {
            next();
            const scene::WaveType w =
                item.kw == Keyword::kw_ramp_wave       ? scene::WaveType::Ramp
                : item.kw == Keyword::kw_triangle_wave ? scene::WaveType::Triangle
                : item.kw == Keyword::kw_sine_wave     ? scene::WaveType::Sine
                : item.kw == Keyword::kw_scallop_wave  ? scene::WaveType::Scallop
                                                       : scene::WaveType::Cubic;
            editPattern([&](scene::Pattern& p) { p.waveType = w; });
            return true;
        }
        case Keyword::kw_poly_wave: {
            next();
            const double e = parseOptionalFloat(1.0);
            editPattern([&](scene::Pattern& p) {
                p.waveType = scene::WaveType::Poly;
                p.exponent = e;
            });
            return true;
        }
        case Keyword::kw_number_of_sides:
        case Keyword::kw_number_of_tiles:
        case Keyword::kw_pattern:
            if (pigment.pattern().kind != scene::PatternKind::Pavement) return false;
            parsePavementItem(pigment.pattern().pavement);
            return true;
        case Keyword::kw_exponent:
        case Keyword::kw_interior:
        case Keyword::kw_exterior: {
            if (pigment.pattern().kind == scene::PatternKind::Pavement &&
                !item.is(Keyword::kw_exponent)) {
                parsePavementItem(pigment.pattern().pavement);
                return true;
            }
            if (pigment.pattern().kind != scene::PatternKind::Fractal) return false;
            next();
            scene::FractalSettings f = pigment.pattern().fractal;
            parseFractalItem(item, f);
            editPattern([&](scene::Pattern& p) { p.fractal = f; });
            return true;
        }
        case Keyword::kw_form: {
            if (pigment.pattern().kind == scene::PatternKind::Pavement) {
                parsePavementItem(pigment.pattern().pavement);
                return true;
            }
            next();
            const Vec3 f = parseVec3();
            editPattern([&](scene::Pattern& p) { p.crackle.form = f; });
            return true;
        }
        case Keyword::kw_metric: {
            next();
            const double m = parseFloat();
            editPattern([&](scene::Pattern& p) { p.crackle.metric = m; });
            return true;
        }
        case Keyword::kw_offset: {
            next();
            const double o = parseFloat();
            editPattern([&](scene::Pattern& p) { p.crackle.offset = o; });
            return true;
        }
        case Keyword::kw_solid:
            next();
            editPattern([&](scene::Pattern& p) { p.crackle.solid = true; });
            return true;
        case Keyword::kw_coords:
        case Keyword::kw_size: {
            if (pigment.pattern().kind != scene::PatternKind::Facets) return false;
            next();
            const double v = parseFloat();
            editPattern([&](scene::Pattern& p) {
                // coords C tilts by C (the cell size stays `size`);
                // measured: the coords value does not scale the cells.
                if (item.kw == Keyword::kw_coords)
                    p.facets.coords = v;
                else
                    p.facets.size = v;
            });
            return true;
        }
        case Keyword::kw_agate_turb: {
            next();
            const double a = parseFloat();
            editPattern([&](scene::Pattern& p) { p.agateTurb = a; });
            return true;
        }
        case Keyword::kw_noise_generator: {
            next();
            const scene::NoiseGenerator g = parseNoiseGenerator(item);
            editPattern([&](scene::Pattern& p) { p.noiseGenerator = g; });
            return true;
        }
        case Keyword::kw_warp: {
            next();
            const scene::Warp w = parseWarp();
            editPattern([&](scene::Pattern& p) { p.addWarp(w); });
            return true;
        }
        default: {
            scene::Pattern p = pigment.pattern();
            scene::Turbulence turb = p.turbulence.value_or(scene::Turbulence{});
            if (!parseTurbulenceItem(turb)) return false;
            p.turbulence = turb;
            pigment.pattern() = p;
            return true;
        }
    }
}

std::shared_ptr<const scene::Normal> Interpreter::parseNormal(const scene::Normal* base,
                                                              scene::Normal* settings) {
    next();  // normal
    expect(Sym::LBrace, "'{' after 'normal'");
    auto normal = parseNormalBody(base, Sym::RBrace, settings);
    expect(Sym::RBrace, "'}' closing 'normal'");
    return normal;
}

std::shared_ptr<const scene::Normal> Interpreter::parseNormalBody(const scene::Normal* base,
                                                                  Sym closing,
                                                                  scene::Normal* settings) {
    const NestingGuard nesting(*this, peek());
    scene::Normal normal = base ? *base : defaultNormal_;
    bool havePattern = base != nullptr;
    // A declared normal to start from.
    if (const Token first = peek(); first.isIdentifier()) {
        const Value* v = lookup(std::string(first.text));
        // A normal identifier, or an element of an array of normals.
        if (v && (std::holds_alternative<NormalPtr>(*v) || arrayHolds<NormalPtr>(*v))) {
            next();
            const Value value = identifierValue(first, v);
            const auto* declared = std::get_if<NormalPtr>(&value);
            if (!declared)
                fail(first, fmt::format("expected a normal, found a {}", valueKindName(value)));
            normal = *declared ? **declared : scene::Normal{};
            havePattern = *declared != nullptr;
        }
    }
    // As in a pigment: transformations after a uv-mapped identifier do
    // nothing (measured).
    const bool uvFrozen = normal.uvMapping && havePattern;
    if (accept(Keyword::kw_uv_mapping)) normal.uvMapping = true;
    // The pattern and its modifiers are parsed like a pigment's; the
    // pigment is a scratch holder for the pattern and its chain.
    scene::Pigment holder;
    holder.setPattern(normal.pattern);
    // An optional bump size follows the pattern, after an optional comma
    // (povray: `gradient x, 5.6`; the fractals write it so).
    auto parseBumpSize = [&] {
        accept(Sym::Comma);
        if (floatFollows()) normal.amount = parseFloat();
    };
    while (!peek().is(closing)) {
        const Token item = peek();
        Transform step;
        if (parseTransformation(step)) {
            if (uvFrozen) continue;
            holder.transform(step);
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
            parsePatternKeyword(holder, true);
            havePattern = true;
            if (holder.pattern().isList() && !peek().is(Keyword::kw_normal)) {
                // A list pattern without normals is a bumpy pattern of its
                // own: its index is sampled, so only the cells' edges tilt.
                closeListPattern(holder.pattern());
                if (normal.mapMode == scene::Normal::MapMode::List)
                    normal.mapMode = scene::Normal::MapMode::None;
                parseBumpSize();
                continue;
            }
            if (holder.pattern().isList()) {
                // A list pattern takes one normal per index.
                normal.mapMode = scene::Normal::MapMode::List;
                normal.map.clear();
                const int count = scene::Pattern::listSize(holder.pattern().kind);
                for (int i = 0; i < count; ++i) {
                    if (i > 0) accept(Sym::Comma);
                    if (!peek().is(Keyword::kw_normal)) break;
                    const Token entryAt = peek();
                    auto entry = parseNormal(nullptr);
                    if (entry && entry->uvMapping)
                        unsupported(entryAt, "uv_mapping in a normal of a list pattern");
                    normal.map.push_back({static_cast<double>(i), std::move(entry)});
                }
                while (static_cast<int>(normal.map.size()) < count)
                    normal.map.push_back({static_cast<double>(normal.map.size()), nullptr});
                closeListPattern(holder.pattern());
                continue;
            }
            if (normal.mapMode == scene::Normal::MapMode::List)
                normal.mapMode = scene::Normal::MapMode::None;
            parseBumpSize();
            continue;
        }
        switch (item.kw) {
            case Keyword::kw_bump_size:
                next();
                normal.amount = parseFloat();
                continue;
            case Keyword::kw_accuracy:
                next();
                normal.accuracy = parseFloat();
                continue;
            case Keyword::kw_normal_map:
                if (normal.mapMode == scene::Normal::MapMode::List)
                    fail(item, "a list pattern takes normals, not a normal_map");
                normal.map = parseNormalMap();
                if (normal.mapMode == scene::Normal::MapMode::None)
                    normal.mapMode = scene::Normal::MapMode::Values;
                continue;
            case Keyword::kw_slope_map:
                normal.slopeMap = parseSlopeMap();
                continue;
            case Keyword::kw_average:
                next();
                normal.mapMode = scene::Normal::MapMode::Average;
                havePattern = true;
                continue;
            case Keyword::kw_color_map:
            case Keyword::kw_colour_map:
            case Keyword::kw_pigment_map:
                fail(item, fmt::format("'{}' is not allowed in a normal", item.text));
            default:
                break;
        }
        if (parseImageNormalItem(normal, holder)) {
            havePattern = true;
            continue;
        }
        if (parsePigmentPatternItem(holder)) continue;
        if (item.kind == TokenKind::Word && item.kw != Keyword::None)
            unsupported(item, fmt::format("'{}' in normal", item.text));
        fail(item, fmt::format("expected a normal item or '{}', found {}",
                               closing == Sym::RBrace ? "}" : "]", describeToken(item)));
    }
    normal.pattern = holder.pattern();
    checkPavement(normal.pattern, peek());
    if (settings) *settings = normal;
    if (!havePattern) return nullptr;  // normal { } without a pattern: no perturbation
    return std::make_shared<const scene::Normal>(normal);
}

// mandel ITERATIONS | julia <C>, ITERATIONS | magnet 1|2 (mandel | julia <C>,)
// ITERATIONS
void Interpreter::parseFractalHead(const Token& kind, scene::FractalSettings& f) {
    using Kind = scene::FractalSettings::Kind;
    f = scene::FractalSettings{};
    Token form = kind;
    int magnetType = 0;
    if (kind.is(Keyword::kw_magnet)) {
        const Token at = peek();
        const double t = parseFloat();
        if (t != 1 && t != 2) fail(at, fmt::format("magnet type must be 1 or 2, found {}", t));
        magnetType = static_cast<int>(t);
        form = next();
        if (!form.is(Keyword::kw_mandel) && !form.is(Keyword::kw_julia))
            fail(form, fmt::format("expected 'mandel' or 'julia' after 'magnet {}', found {}",
                                   magnetType, describeToken(form)));
    }
    const bool julia = form.is(Keyword::kw_julia);
    f.kind = magnetType == 0   ? (julia ? Kind::Julia : Kind::Mandel)
             : magnetType == 1 ? (julia ? Kind::Magnet1Julia : Kind::Magnet1Mandel)
                               : (julia ? Kind::Magnet2Julia : Kind::Magnet2Mandel);
    if (julia) {
        const VectorValue c = parseVector();
        f.cx = c.v[0];
        f.cy = c.v[1];
        accept(Sym::Comma);
    }
    const Token at = peek();
    const double n = parseFloat();
    if (n < 1) fail(at, fmt::format("{} needs at least one iteration, found {}", kind.text, n));
    f.iterations = static_cast<int>(n);
}

// exponent N | interior TYPE, FACTOR | exterior TYPE, FACTOR (after the
// keyword). povray rejects the same values (types outside 0..6, exponent
// on a magnet).
void Interpreter::parseFractalItem(const Token& item, scene::FractalSettings& f) {
    if (item.is(Keyword::kw_exponent)) {
        if (f.isMagnet()) fail(item, "'exponent' can only be used with mandel or julia");
        const Token at = peek();
        const double e = parseFloat();
        if (e < 2 || e > 33 || e != std::floor(e))
            fail(at,
                 fmt::format("fractal exponent must be a whole number from 2 to 33, found {}", e));
        f.exponent = static_cast<int>(e);
        return;
    }
    const Token at = peek();
    const double typeValue = parseFloat();
    accept(Sym::Comma);
    const double factor = parseFloat();
    const int type = static_cast<int>(typeValue);  // truncated like povray's
    if (type < 0 || type > 6)
        fail(at, fmt::format("fractal {} type must be 0 to 6, found {}", item.text, typeValue));
    if (item.is(Keyword::kw_interior)) {
        f.interiorType = type;
        f.interiorFactor = factor;
    } else {
        f.exteriorType = type;
        f.exteriorFactor = factor;
    }
}

scene::NoiseGenerator Interpreter::parseNoiseGenerator(const Token& at) {
    const double g = parseFloat();
    if (g == 1) return scene::NoiseGenerator::Original;
    if (g == 2) return scene::NoiseGenerator::RangeCorrected;
    if (g == 3) unsupported(at, "noise_generator 3");
    fail(at, fmt::format("noise_generator must be 1, 2 or 3, found {}", g));
}

bool Interpreter::parseTurbulenceItem(scene::Turbulence& turb) {
    const Token item = peek();
    switch (item.kw) {
        case Keyword::kw_turbulence: {
            next();
            turb.amount = parseVec3();
            return true;
        }
        case Keyword::kw_octaves: {
            next();
            const double o = parseFloat();
            // povray clamps octaves to 1..10.
            turb.octaves = std::clamp(static_cast<int>(o), 1, 10);
            return true;
        }
        case Keyword::kw_omega: {
            next();
            turb.omega = static_cast<float>(parseFloat());
            return true;
        }
        case Keyword::kw_lambda: {
            next();
            turb.lambda = static_cast<float>(parseFloat());
            return true;
        }
        default:
            return false;
    }
}

scene::Warp Interpreter::parseWarp() {
    expect(Sym::LBrace, "'{' after 'warp'");
    scene::Warp w;
    const Token kind = next();
    if (kind.is(Keyword::kw_turbulence)) {
        w.kind = scene::Warp::Kind::Turbulence;
        w.turb.amount = parseVec3();
        while (parseTurbulenceItem(w.turb)) {
        }
    } else if (kind.is(Keyword::kw_repeat)) {
        w.kind = scene::Warp::Kind::Repeat;
        const Vec3 dir = parseVec3();
        int axes = 0;
        for (int i = 0; i < 3; ++i)
            if (dir[i] != 0) {
                w.axis = i;
                ++axes;
            }
        if (axes != 1) fail(kind, "warp repeat needs a direction along one axis (x, y or z)");
        w.width = dir[w.axis];
        for (;;) {
            const Token t = peek();
            if (t.is(Keyword::kw_offset)) {
                next();
                w.offset = parseVec3();
            } else if (t.is(Keyword::kw_flip)) {
                next();
                const Vec3 f = parseVec3();
                for (int i = 0; i < 3; ++i) w.flip[i] = f[i] != 0;
            } else {
                break;
            }
        }
    } else if (kind.is(Keyword::kw_black_hole)) {
        w.kind = scene::Warp::Kind::BlackHole;
        w.center = parseVec3();
        accept(Sym::Comma);
        w.radius = parseFloat();
        for (;;) {
            const Token t = peek();
            if (t.is(Keyword::kw_strength)) {
                next();
                w.strength = parseFloat();
            } else if (t.is(Keyword::kw_falloff)) {
                next();
                w.falloff = parseFloat();
            } else if (t.is(Keyword::kw_inverse)) {
                next();
                w.inverse = true;
            } else if (t.is(Keyword::kw_repeat) || t.is(Keyword::kw_turbulence)) {
                unsupported(t, fmt::format("'{}' in warp {{ black_hole }}", t.text));
            } else {
                break;
            }
        }
    } else if (kind.is(Keyword::kw_cylindrical) || kind.is(Keyword::kw_spherical) ||
               kind.is(Keyword::kw_toroidal)) {
        // cylindrical | spherical | toroidal [orientation V] [dist_exp E]
        // [major_radius R] (toroidal only; povray rejects it elsewhere).
        w.kind = kind.is(Keyword::kw_cylindrical) ? scene::Warp::Kind::Cylindrical
                 : kind.is(Keyword::kw_spherical) ? scene::Warp::Kind::Spherical
                                                  : scene::Warp::Kind::Toroidal;
        for (;;) {
            const Token t = peek();
            if (t.is(Keyword::kw_orientation)) {
                next();
                const Vec3 o = parseVec3();
                // povray normalises it (a zero vector gives NaN there).
                if (length(o) == 0) fail(t, "warp orientation vector is zero");
                w.orientation = normalize(o);
            } else if (t.is(Keyword::kw_dist_exp)) {
                next();
                w.distExp = parseFloat();
            } else if (t.is(Keyword::kw_major_radius) && w.kind == scene::Warp::Kind::Toroidal) {
                next();
                w.majorRadius = parseFloat();
            } else {
                break;
            }
        }
    } else if (kind.is(Keyword::kw_planar)) {
        // planar [NORMAL, DISTANCE]: the distance is required after a normal.
        w.kind = scene::Warp::Kind::Planar;
        if (!peek().is(Sym::RBrace)) {
            const Token at = peek();
            const Vec3 o = parseVec3();
            if (length(o) == 0) fail(at, "warp planar normal is zero");
            w.orientation = normalize(o);
            accept(Sym::Comma);
            w.planeDistance = parseFloat();
        }
    } else if (kind.kind == TokenKind::Word && kind.kw != Keyword::None) {
        unsupported(kind, fmt::format("warp {{ {} }}", kind.text));
    } else {
        fail(kind, fmt::format("expected a warp type in 'warp', found {}", describeToken(kind)));
    }
    expect(Sym::RBrace, "'}' after a warp");
    return w;
}

scene::ColorMap Interpreter::parseColorMap() {
    const Token kw = next();  // color_map
    expect(Sym::LBrace, "'{' after 'color_map'");
    if (const BlendMapValue* m = blendMapIdentifier(BlendMapValue::Kind::Color)) {
        expect(Sym::RBrace, "'}' after a color_map identifier");
        return m->colors;
    }
    std::vector<scene::ColorMap::Entry> entries;
    for (;;) {
        if (accept(Sym::RBrace)) break;
        const Token open = peek();
        expect(Sym::LBracket, "'[' or '}' in color_map");
        const double v1 = parseMapValue();
        accept(Sym::Comma);
        if (peek().kind == TokenKind::Number) {
            // [v1, v2 color C1 color C2] or, without the comma, [v1 v2 color
            // C1 color C2] (woodmaps.inc, stars.inc): a band from C1 to C2.
            // povray wants 'color' before a colour here, so a number after
            // the first value always starts the second.
            const double v2 = parseFloat();
            const Color c1 = parseColor();
            const Color c2 = parseColor();
            entries.push_back({v1, c1});
            entries.push_back({v2, c2});
        } else {
            entries.push_back({v1, parseColor()});
        }
        expect(Sym::RBracket, "']' after a color_map entry");
        if (entries.size() > scene::ColorMap::kMaxEntries)
            fail(open,
                 fmt::format("a color_map holds at most {} entries", scene::ColorMap::kMaxEntries));
    }
    if (entries.empty()) fail(kw, "color_map needs at least one entry");
    // Entries out of order are kept as written: povray accepts them
    // (woods.inc T_Wood32 has [0.95 ..] [0.90 ..]) and ColorMap::at scans
    // them in order as povray does.
    return scene::ColorMap(std::move(entries));
}

std::vector<scene::Pigment::MapEntry> Interpreter::parsePigmentMap() {
    const Token kw = next();  // pigment_map
    expect(Sym::LBrace, "'{' after 'pigment_map'");
    if (const BlendMapValue* m = blendMapIdentifier(BlendMapValue::Kind::Pigment)) {
        expect(Sym::RBrace, "'}' after a pigment_map identifier");
        return m->pigments;
    }
    std::vector<scene::Pigment::MapEntry> entries;
    for (;;) {
        if (accept(Sym::RBrace)) break;
        expect(Sym::LBracket, "'[' or '}' in pigment_map");
        const double v = parseMapValue(true);
        accept(Sym::Comma);
        // [v PIGMENT_BODY]: a colour, a pigment identifier, a pattern...
        auto entry = std::make_shared<scene::Pigment>();
        parsePigmentBody(*entry, Sym::RBracket);
        entries.push_back({v, std::move(entry)});
        expect(Sym::RBracket, "']' after a pigment_map entry");
    }
    if (entries.empty()) fail(kw, "pigment_map needs at least one entry");
    if (entries.size() > scene::ColorMap::kMaxEntries)
        fail(kw,
             fmt::format("a pigment_map holds at most {} entries", scene::ColorMap::kMaxEntries));
    // Not checked for order: under `average` the values are weights.
    return entries;
}

}  // namespace frameray::sdl
