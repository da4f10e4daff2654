// media { } and density { } (POV-Ray 3.7): the sampling settings, the three
// effects (absorption, emission, scattering with its phase function) and
// the density patterns, which reuse the pigment pattern parser: a density
// is a pigment whose colour is the density per channel.
#include <fmt/format.h>

#include "sdl/builders.h"

namespace frameray::sdl {

namespace {

// scattering { TYPE, ... }: the types povray 3.7 knows.
scene::ScatteringType scatteringType(int type) {
    switch (type) {
        case 1:
            return scene::ScatteringType::Isotropic;
        case 2:
            return scene::ScatteringType::MieHazy;
        case 3:
            return scene::ScatteringType::MieMurky;
        case 4:
            return scene::ScatteringType::Rayleigh;
        case 5:
            return scene::ScatteringType::HenyeyGreenstein;
        default:
            return scene::ScatteringType::None;
    }
}

// What may start a constant density (a colour expression).
bool startsDensityColor(const Token& t) {
    static constexpr Keyword kColor[] = {
        Keyword::kw_color, Keyword::kw_colour, Keyword::kw_rgb,     Keyword::kw_rgbf,
        Keyword::kw_rgbt,  Keyword::kw_rgbft,  Keyword::kw_srgb,    Keyword::kw_srgbf,
        Keyword::kw_srgbt, Keyword::kw_srgbft, Keyword::kw_red,     Keyword::kw_green,
        Keyword::kw_blue,  Keyword::kw_filter, Keyword::kw_transmit};
    if (t.isIdentifier() || t.is(Sym::Less) || t.kind == TokenKind::Number || t.is(Sym::LParen))
        return true;
    for (const Keyword k : kColor)
        if (t.is(k)) return true;
    return false;
}

}  // namespace

// Defined below.
static DensityPtr parseDensityBody(BuildContext& c, Sym closing);
static std::vector<scene::Pigment::MapEntry> parseDensityMap(BuildContext& c);

DensityPtr parseDensity(BuildContext& c) {
    Reader& r = c.reader;
    r.next();  // density
    r.expect(Sym::LBrace, "'{' after 'density'");
    DensityPtr d = parseDensityBody(c, Sym::RBrace);
    r.expect(Sym::RBrace, "'}' closing 'density'");
    return d;
}

static DensityPtr parseDensityBody(BuildContext& c, Sym closing) {
    Reader& r = c.reader;
    auto pigment = std::make_shared<scene::Pigment>(scene::defaultDensity());
    const Token first = r.peek();
    if (first.isIdentifier()) {
        const Value* v = r.lookup(first);
        if (v && std::holds_alternative<DensityPtr>(*v)) {
            r.next();
            *pigment = *std::get<DensityPtr>(*v)->pigment;
        }
    }
    while (!r.peek().is(closing)) {
        const Token item = r.peek();
        Transform step;
        if (r.parseTransformation(step)) {
            pigment->transform(step);
            continue;
        }
        if (item.is(Keyword::kw_density_map)) {
            pigment->setPigmentMap(parseDensityMap(c));
            continue;
        }
        if (item.is(Keyword::kw_pigment_map) || item.is(Keyword::kw_uv_mapping) ||
            item.is(Keyword::kw_image_map))
            r.fail(item, fmt::format("'{}' is not allowed in a density", item.text));
        if (parsePigmentPatternItem(c, *pigment)) continue;
        if (startsDensityColor(item)) {
            pigment->setSolid(r.parseColor());
            continue;
        }
        if (item.kind == TokenKind::Word && item.kw != Keyword::None)
            r.unsupported(item, fmt::format("'{}' in density", item.text));
        r.fail(item, fmt::format("expected a density item or '}}', found {}", describeToken(item)));
    }
    pigment->settleDefaultColorMap();
    return std::make_shared<const DensityValue>(DensityValue{pigment});
}

static std::vector<scene::Pigment::MapEntry> parseDensityMap(BuildContext& c) {
    Reader& r = c.reader;
    r.next();  // density_map
    r.expect(Sym::LBrace, "'{' after 'density_map'");
    std::vector<scene::Pigment::MapEntry> entries;
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        r.expect(Sym::LBracket, "'[' or '}' in density_map");
        const double value = parseMapValue(c);
        r.accept(Sym::Comma);
        // An entry is a density's body: a density identifier, a pattern or
        // a colour, with modifiers.
        PigmentPtr pigment = parseDensityBody(c, Sym::RBracket)->pigment;
        r.expect(Sym::RBracket, "']' after a density_map entry");
        entries.push_back({value, std::move(pigment)});
    }
    return entries;
}

MediaPtr parseMedia(BuildContext& c) {
    Reader& r = c.reader;
    r.next();  // media
    r.expect(Sym::LBrace, "'{' after 'media'");
    scene::Media m;
    const Token first = r.peek();
    if (first.isIdentifier()) {
        const Value* v = r.lookup(first);
        if (v && std::holds_alternative<MediaPtr>(*v)) {
            r.next();
            m = *std::get<MediaPtr>(*v);
        }
    }
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        const Token t = r.peek();
        Transform step;
        if (r.parseTransformation(step)) {
            m.transformBy(step);
            continue;
        }
        if (t.is(Keyword::kw_density)) {
            m.densities.push_back(parseDensity(c)->pigment);
            continue;
        }
        r.next();
        switch (t.kw) {
            case Keyword::kw_method: {
                const int method = static_cast<int>(r.parseFloat());
                if (method < 1 || method > 3) r.fail(t, "Unknown media sampling method.");
                m.method = method;
                break;
            }
            case Keyword::kw_intervals:
                m.intervals = static_cast<int>(r.parseFloat());
                if (m.intervals < 1) r.fail(t, "At least one interval is needed in media.");
                break;
            case Keyword::kw_samples:
                m.samplesMin = static_cast<int>(r.parseFloat());
                m.samplesMax = m.samplesMin;
                if (r.accept(Sym::Comma)) m.samplesMax = static_cast<int>(r.parseFloat());
                if (m.samplesMin < 1)
                    r.fail(t, "At least one sample per interval is needed in media.");
                if (m.samplesMax < m.samplesMin)
                    r.fail(t,
                           "Maximum number of samples per interval smaller than minimum "
                           "number.");
                break;
            case Keyword::kw_confidence:
                m.confidence = r.parseFloat();
                break;
            case Keyword::kw_variance:
                m.variance = r.parseFloat();
                break;
            case Keyword::kw_ratio:
                m.ratio = r.parseFloat();
                break;
            case Keyword::kw_aa_level:
                m.aaLevel = static_cast<int>(r.parseFloat());
                if (m.aaLevel < 1) r.fail(t, "aa_level in media must be at least one.");
                break;
            case Keyword::kw_aa_threshold:
                m.aaThreshold = r.parseFloat();
                break;
            case Keyword::kw_jitter:
                m.jitter = r.parseFloat();
                break;
            case Keyword::kw_absorption:
                m.absorption = r.parseColor().rgb;
                break;
            case Keyword::kw_emission:
                m.emission = r.parseColor().rgb;
                break;
            case Keyword::kw_scattering: {
                r.expect(Sym::LBrace, "'{' after 'scattering'");
                const Token type = r.peek();
                const int number = static_cast<int>(r.parseFloat());
                m.scatteringType = scatteringType(number);
                if (m.scatteringType == scene::ScatteringType::None)
                    r.fail(type, "Unknown media scattering type.");
                r.accept(Sym::Comma);
                m.scattering = r.parseColor().rgb;
                for (;;) {
                    if (r.accept(Sym::RBrace)) break;
                    const Token s = r.next();
                    if (s.is(Keyword::kw_eccentricity))
                        m.eccentricity = r.parseFloat();
                    else if (s.is(Keyword::kw_extinction))
                        m.extinction = r.parseFloat();
                    else
                        r.fail(s, fmt::format("expected eccentricity, extinction or '}}' in "
                                              "scattering, found {}",
                                              describeToken(s)));
                }
                break;
            }
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    r.unsupported(t, fmt::format("'{}' in media", t.text));
                r.fail(t, fmt::format("expected a media item or '}}', found {}", describeToken(t)));
        }
    }
    m.prepareSampling();
    return std::make_shared<const scene::Media>(std::move(m));
}

}  // namespace frameray::sdl
