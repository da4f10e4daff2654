// The three photons { } blocks of POV-Ray 3.7: in global_settings (turns
// photon mapping on), in an object (its part: target, reflection,
// refraction, collect, pass_through) and in a light_source (which photons
// it shoots). What they mean is render/photons.h's; here only their syntax,
// checked against povray 3.7 (gather and expand_thresholds need both
// values, radius takes up to four with any left out, count wins over
// spacing whatever their order, refraction/reflection/collect need a
// value). Photon map files: save_file names where the shot maps go,
// load_file reads a map frameray saved (render/photon_file.h); povray's
// own files are refused.
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>

#include "sdl/builders.h"

namespace frameray::sdl {

namespace {

// What povray does with a non-positive count or spacing is to shoot
// nothing useful; keep the values sane for the shooter.
int positiveInt(double v) {
    return v >= 1 ? static_cast<int>(v) : 1;
}

// The loop all three blocks share: `{`, settings until `}`. `setting`
// reads one setting and says whether it knew the token; an unknown keyword
// is "not supported yet" (it may be a 3.7 setting we lack), anything else
// an error. `where` names the block in messages ("light photons").
template <class Setting>
void parseSettings(Reader& r, std::string_view where, Setting&& setting) {
    r.expect(Sym::LBrace, "'{' after 'photons'");
    while (!r.accept(Sym::RBrace)) {
        const Token t = r.next();
        if (setting(t)) continue;
        if (t.kind == TokenKind::Word && t.kw != Keyword::None)
            r.unsupported(t, fmt::format("'{}' in {}", t.text, where));
        r.fail(t, fmt::format("expected a {} setting or '}}', found {}", where, describeToken(t)));
    }
}

// refraction and reflection, alike in objects and lights.
bool parseOpticsSetting(Reader& r, const Token& t, scene::PhotonToggle& refraction,
                        scene::PhotonToggle& reflection) {
    if (t.kw != Keyword::kw_refraction && t.kw != Keyword::kw_reflection) return false;
    (t.kw == Keyword::kw_refraction ? refraction : reflection) =
        r.parseFloat() != 0 ? scene::PhotonToggle::On : scene::PhotonToggle::Off;
    return true;
}

}  // namespace

void parseGlobalPhotons(BuildContext& c, scene::PhotonSettings& s) {
    Reader& r = c.reader;
    std::optional<Token> saveAt, loadAt;
    std::string saveName;
    parseSettings(r, "global photons", [&](const Token& t) {
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
                // media max_steps [, factor]
                s.mediaMaxSteps = std::max(0, static_cast<int>(r.parseFloat()));
                if (r.accept(Sym::Comma)) s.mediaFactor = r.parseFloat();
                break;
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
                saveAt = t;
                saveName = r.parsePathname();
                break;
            case Keyword::kw_load_file:
                loadAt = t;
                s.loadFile = r.parsePathname();
                break;
            default:
                return false;
        }
        return true;
    });
    // povray 3.7 (measured): given both, it warns and loads.
    if (saveAt && loadAt) {
        r.warn(*saveAt, "Cannot both load and save photon map. Now switching to load mode.");
        saveAt.reset();
    }
    if (saveAt) s.saveFile = r.fileToWrite(saveName, *saveAt).string();
    if (loadAt) {
        auto bytes =
            std::make_shared<const std::string>(r.readWholeFile(s.loadFile, *loadAt, "photon map"));
        if (!bytes->starts_with(scene::kPhotonFileMagic))
            r.fail(*loadAt,
                   fmt::format("'{}' is not a frameray photon map: frameray loads only the maps it "
                               "saves itself with save_file, not povray's",
                               s.loadFile));
        s.loaded = std::move(bytes);
    }
}

void parseObjectPhotons(BuildContext& c, scene::ObjectPhotons& p, const Token& block) {
    Reader& r = c.reader;
    p.given = true;
    parseSettings(r, "object photons", [&](const Token& t) {
        if (parseOpticsSetting(r, t, p.refraction, p.reflection)) return true;
        switch (t.kw) {
            case Keyword::kw_target:
                p.target = r.floatFollows() ? r.parseFloat() : 1.0;
                break;
            case Keyword::kw_collect:
                p.collect = r.parseFloat() != 0;
                break;
            case Keyword::kw_pass_through:
                p.passThrough = r.parseOptionalBool();
                break;
            default:
                return false;
        }
        return true;
    });
    // povray 3.7's check, made when the block ends (measured wording; it
    // warns whether or not refraction was asked for).
    if (p.passThrough && p.target > 0) {
        r.warn(block, "Cannot use pass_through with refraction & target. Turning off refraction.");
        p.refraction = scene::PhotonToggle::Off;
    }
}

void parseLightPhotons(BuildContext& c, scene::LightPhotons& p) {
    Reader& r = c.reader;
    parseSettings(r, "light photons", [&](const Token& t) {
        if (parseOpticsSetting(r, t, p.refraction, p.reflection)) return true;
        if (t.kw != Keyword::kw_area_light) return false;
        p.areaLight = r.parseOptionalBool();
        return true;
    });
}

}  // namespace frameray::sdl
