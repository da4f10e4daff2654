// The three photons { } blocks of POV-Ray 3.7: in global_settings (turns
// photon mapping on), in an object (its part: target, reflection,
// refraction, collect, pass_through) and in a light_source (which photons
// it shoots). What they mean is render/photons.h's; here only their syntax,
// checked against povray 3.7 (gather and expand_thresholds need both
// values, radius takes up to four with any left out, count wins over
// spacing whatever their order, refraction/reflection/collect need a
// value).
#include <fmt/format.h>

#include "sdl/interpreter.h"

namespace frameray::sdl {

namespace {

// What povray does with a non-positive count or spacing is to shoot
// nothing useful; keep the values sane for the shooter.
int positiveInt(double v) {
    return v >= 1 ? static_cast<int>(v) : 1;
}

}  // namespace

void Interpreter::parseGlobalPhotons(scene::PhotonSettings& s) {
    expect(Sym::LBrace, "'{' after 'photons'");
    for (;;) {
        if (accept(Sym::RBrace)) break;
        const Token t = next();
        switch (t.kw) {
            case Keyword::kw_spacing:
                s.spacing = parseFloat();
                break;
            case Keyword::kw_count:
                s.count = positiveInt(parseFloat());
                break;
            case Keyword::kw_gather:
                s.gatherMin = static_cast<int>(parseFloat());
                expect(Sym::Comma, "',' between the two gather values");
                s.gatherMax = static_cast<int>(parseFloat());
                break;
            case Keyword::kw_media:
                s.mediaMaxSteps = static_cast<int>(parseFloat());
                if (accept(Sym::Comma)) s.mediaFactor = parseFloat();
                break;
            case Keyword::kw_jitter:
                s.jitter = parseFloat();
                break;
            case Keyword::kw_max_trace_level:
                s.maxTraceLevel = static_cast<int>(parseFloat());
                break;
            case Keyword::kw_adc_bailout:
                s.adcBailout = parseFloat();
                break;
            case Keyword::kw_autostop:
                s.autostop = parseFloat();
                break;
            case Keyword::kw_expand_thresholds:
                s.expandIncrease = parseFloat();
                expect(Sym::Comma, "',' between the two expand_thresholds values");
                s.expandMin = static_cast<int>(parseFloat());
                break;
            case Keyword::kw_radius: {
                // radius [R] [, [M] [, [R media] [, [M media]]]]: any value may
                // be left out, its comma kept.
                double* slots[] = {&s.radius, &s.radiusMultiplier, &s.mediaRadius,
                                   &s.mediaRadiusMultiplier};
                for (size_t i = 0; i < 4; ++i) {
                    if (i > 0 && !accept(Sym::Comma)) break;
                    if (floatFollows()) *slots[i] = parseFloat();
                }
                break;
            }
            case Keyword::kw_save_file:
                s.saveFile = parsePathname();
                break;
            case Keyword::kw_load_file:
                s.loadFile = parsePathname();
                break;
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    unsupported(t, fmt::format("'{}' in global photons", t.text));
                fail(t,
                     fmt::format("expected a photons setting or '}}', found {}", describeToken(t)));
        }
    }
}

void Interpreter::parseObjectPhotons(scene::ObjectPhotons& p, const Token& block) {
    expect(Sym::LBrace, "'{' after 'photons'");
    p.given = true;
    for (;;) {
        if (accept(Sym::RBrace)) break;
        const Token t = next();
        switch (t.kw) {
            case Keyword::kw_target:
                p.target = floatFollows() ? parseFloat() : 1.0;
                break;
            case Keyword::kw_refraction:
                p.refraction = parseFloat() != 0;
                break;
            case Keyword::kw_reflection:
                p.reflection = parseFloat() != 0;
                break;
            case Keyword::kw_collect:
                p.collect = parseFloat() != 0;
                break;
            case Keyword::kw_pass_through:
                p.passThrough = parseOptionalBool();
                break;
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    unsupported(t, fmt::format("'{}' in object photons", t.text));
                fail(t, fmt::format("expected an object photons setting or '}}', found {}",
                                    describeToken(t)));
        }
    }
    // povray 3.7's check, made when the block ends (measured wording; it
    // warns whether or not refraction was asked for).
    if (p.passThrough && p.target > 0) {
        warn(block, "Cannot use pass_through with refraction & target. Turning off refraction.");
        p.refraction = false;
    }
}

void Interpreter::parseLightPhotons(scene::LightPhotons& p) {
    expect(Sym::LBrace, "'{' after 'photons'");
    for (;;) {
        if (accept(Sym::RBrace)) break;
        const Token t = next();
        switch (t.kw) {
            case Keyword::kw_refraction:
                p.refraction = parseFloat() != 0;
                break;
            case Keyword::kw_reflection:
                p.reflection = parseFloat() != 0;
                break;
            case Keyword::kw_area_light:
                p.areaLight = parseOptionalBool();
                break;
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    unsupported(t, fmt::format("'{}' in light photons", t.text));
                fail(t, fmt::format("expected a light photons setting or '}}', found {}",
                                    describeToken(t)));
        }
    }
}

}  // namespace frameray::sdl
