// The three photons { } blocks of POV-Ray 3.7: in global_settings (turns
// photon mapping on), in an object (its part: target, reflection,
// refraction, collect, pass_through) and in a light_source (which photons
// it shoots). What they mean is render/photons.h's; here only their syntax,
// checked against povray 3.7 (gather and expand_thresholds need both
// values, radius takes up to four with any left out, count wins over
// spacing whatever their order, refraction/reflection/collect need a
// value). Media photons and photon map files (save_file, load_file) stop
// as not supported yet.
#include <fmt/format.h>

#include "sdl/builders.h"

namespace frameray::sdl {

namespace {

// What povray does with a non-positive count or spacing is to shoot
// nothing useful; keep the values sane for the shooter.
int positiveInt(double v) {
    return v >= 1 ? static_cast<int>(v) : 1;
}

}  // namespace

void parseGlobalPhotons(BuildContext& c, scene::PhotonSettings& s) {
    Reader& r = c.reader;
    r.expect(Sym::LBrace, "'{' after 'photons'");
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        const Token t = r.next();
        switch (t.kw) {
            case Keyword::kw_spacing:
                s.spacing = r.parseFloat();
                break;
            case Keyword::kw_count:
                s.count = positiveInt(r.parseFloat());
                break;
            case Keyword::kw_gather:
                s.gatherMin = static_cast<int>(r.parseFloat());
                r.expect(Sym::Comma, "',' between the two gather values");
                s.gatherMax = static_cast<int>(r.parseFloat());
                break;
            case Keyword::kw_media:
                // Photons are neither stored in media nor gathered there yet.
                r.unsupported(t, "photons in media (global photons 'media')");
            case Keyword::kw_jitter:
                s.jitter = r.parseFloat();
                break;
            case Keyword::kw_max_trace_level:
                s.maxTraceLevel = static_cast<int>(r.parseFloat());
                break;
            case Keyword::kw_adc_bailout:
                s.adcBailout = r.parseFloat();
                break;
            case Keyword::kw_autostop:
                s.autostop = r.parseFloat();
                break;
            case Keyword::kw_expand_thresholds:
                s.expandIncrease = r.parseFloat();
                r.expect(Sym::Comma, "',' between the two expand_thresholds values");
                s.expandMin = static_cast<int>(r.parseFloat());
                break;
            case Keyword::kw_radius: {
                // radius [R] [, [M] [, [R media] [, [M media]]]]: any value may
                // be left out, its comma kept.
                double* slots[] = {&s.radius, &s.radiusMultiplier, &s.mediaRadius,
                                   &s.mediaRadiusMultiplier};
                for (size_t i = 0; i < 4; ++i) {
                    if (i > 0 && !r.accept(Sym::Comma)) break;
                    if (r.floatFollows()) *slots[i] = r.parseFloat();
                }
                break;
            }
            case Keyword::kw_save_file:
            case Keyword::kw_load_file:
                r.unsupported(t, fmt::format("photon map files ('{}')", t.text));
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    r.unsupported(t, fmt::format("'{}' in global photons", t.text));
                r.fail(t, fmt::format("expected a photons setting or '}}', found {}",
                                      describeToken(t)));
        }
    }
}

void parseObjectPhotons(BuildContext& c, scene::ObjectPhotons& p, const Token& block) {
    Reader& r = c.reader;
    r.expect(Sym::LBrace, "'{' after 'photons'");
    p.given = true;
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        const Token t = r.next();
        switch (t.kw) {
            case Keyword::kw_target:
                p.target = r.floatFollows() ? r.parseFloat() : 1.0;
                break;
            case Keyword::kw_refraction:
                p.refraction = r.parseFloat() != 0;
                break;
            case Keyword::kw_reflection:
                p.reflection = r.parseFloat() != 0;
                break;
            case Keyword::kw_collect:
                p.collect = r.parseFloat() != 0;
                break;
            case Keyword::kw_pass_through:
                p.passThrough = r.parseOptionalBool();
                break;
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    r.unsupported(t, fmt::format("'{}' in object photons", t.text));
                r.fail(t, fmt::format("expected an object photons setting or '}}', found {}",
                                      describeToken(t)));
        }
    }
    // povray 3.7's check, made when the block ends (measured wording; it
    // warns whether or not refraction was asked for).
    if (p.passThrough && p.target > 0) {
        r.warn(block, "Cannot use pass_through with refraction & target. Turning off refraction.");
        p.refraction = false;
    }
}

void parseLightPhotons(BuildContext& c, scene::LightPhotons& p) {
    Reader& r = c.reader;
    r.expect(Sym::LBrace, "'{' after 'photons'");
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        const Token t = r.next();
        switch (t.kw) {
            case Keyword::kw_refraction:
                p.refraction = r.parseFloat() != 0;
                break;
            case Keyword::kw_reflection:
                p.reflection = r.parseFloat() != 0;
                break;
            case Keyword::kw_area_light:
                p.areaLight = r.parseOptionalBool();
                break;
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    r.unsupported(t, fmt::format("'{}' in light photons", t.text));
                r.fail(t, fmt::format("expected a light photons setting or '}}', found {}",
                                      describeToken(t)));
        }
    }
}

}  // namespace frameray::sdl
