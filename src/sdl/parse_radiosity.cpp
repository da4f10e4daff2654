// radiosity { } in global_settings and in objects. Values are checked
// with povray 3.7's ranges and messages (measured); the settings go to
// scene::RadiositySettings, the object's to scene::Object.
#include <fmt/format.h>

#include <algorithm>

#include "sdl/builders.h"

namespace frameray::sdl {

namespace {

// A check povray makes on one value once it is read: the value is refused
// with `message` unless it is within [low, high] (exclusive where asked).
struct RangeCheck {
    double low;
    double high;
    bool lowExclusive;
    const char* message;

    bool accepts(double v) const { return (lowExclusive ? v > low : v >= low) && v <= high; }
};

constexpr double kHuge = 1e300;

// The float settings: the keyword, the member it sets and the check.
struct FloatSetting {
    Keyword kw;
    double scene::RadiositySettings::*member;
    RangeCheck check;
};
const FloatSetting kFloatSettings[] = {
    {Keyword::kw_error_bound,
     &scene::RadiositySettings::errorBound,
     {0.0, kHuge, true, "Radiosity error bound must be a positive number."}},
    {Keyword::kw_low_error_factor,
     &scene::RadiositySettings::lowErrorFactor,
     {0.0, kHuge, true, "Radiosity low error factor must be a positive number."}},
    {Keyword::kw_pretrace_start,
     &scene::RadiositySettings::pretraceStart,
     {0.0, 1.0, true, "Radiosity pretrace start must be greater than 0 and no higher than 1."}},
    {Keyword::kw_pretrace_end,
     &scene::RadiositySettings::pretraceEnd,
     {0.0, 1.0, true, "Radiosity pretrace end must be greater than 0 and no higher than 1."}},
    {Keyword::kw_gray_threshold,
     &scene::RadiositySettings::grayThreshold,
     {0.0, 1.0, false, "Radiosity gray threshold must be from 0.0 to 1.0."}},
    {Keyword::kw_brightness,
     &scene::RadiositySettings::brightness,
     {0.0, kHuge, true, "Radiosity brightness must be a positive number."}},
    {Keyword::kw_adc_bailout,
     &scene::RadiositySettings::adcBailout,
     {0.0, kHuge, true, "ADC Bailout must be a positive number."}},
    {Keyword::kw_minimum_reuse,
     &scene::RadiositySettings::minimumReuse,
     {-kHuge, kHuge, false, ""}},
    {Keyword::kw_maximum_reuse,
     &scene::RadiositySettings::maximumReuse,
     {-kHuge, kHuge, false, ""}},
    {Keyword::kw_max_sample, &scene::RadiositySettings::maxSample, {-kHuge, kHuge, false, ""}},
};

// The switches: the keyword and the member it turns on or off.
struct BoolSetting {
    Keyword kw;
    bool scene::RadiositySettings::*member;
};
const BoolSetting kBoolSettings[] = {
    {Keyword::kw_always_sample, &scene::RadiositySettings::alwaysSample},
    {Keyword::kw_normal, &scene::RadiositySettings::normal},
    {Keyword::kw_media, &scene::RadiositySettings::media},
    {Keyword::kw_subsurface, &scene::RadiositySettings::subsurface},
};

}  // namespace

void parseRadiositySettings(BuildContext& c, const Token& start) {
    Reader& r = c.reader;
    r.expect(Sym::LBrace, "'{' after 'radiosity'");
    scene::RadiositySettings rs =
        c.scene.globals.radiosity ? *c.scene.globals.radiosity : scene::RadiositySettings{};
    bool minimumGiven = false, maximumGiven = false;
    auto checked = [&](const Token& at, double v, const RangeCheck& check) {
        if (check.message[0] && !check.accepts(v)) r.fail(at, check.message);
        return v;
    };
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        const Token t = r.next();
        if (const auto* f = std::find_if(std::begin(kFloatSettings), std::end(kFloatSettings),
                                         [&](const FloatSetting& s) { return t.is(s.kw); });
            f != std::end(kFloatSettings)) {
            rs.*(f->member) = checked(t, r.parseFloat(), f->check);
            minimumGiven |= t.is(Keyword::kw_minimum_reuse);
            maximumGiven |= t.is(Keyword::kw_maximum_reuse);
            continue;
        }
        if (const auto* b = std::find_if(std::begin(kBoolSettings), std::end(kBoolSettings),
                                         [&](const BoolSetting& s) { return t.is(s.kw); });
            b != std::end(kBoolSettings)) {
            rs.*(b->member) = r.parseOptionalBool();
            continue;
        }
        switch (t.kw) {
            case Keyword::kw_count: {
                rs.count = static_cast<int>(
                    checked(t, r.parseFloat(),
                            {0.0, kHuge, true, "Radiosity count must be a positive number."}));
                if (r.accept(Sym::Comma))
                    rs.directionPool = static_cast<int>(checked(
                        t, r.parseFloat(),
                        {0.0, kHuge, true, "Radiosity direction pool size must be positive."}));
                if (rs.count > rs.directionPool)
                    r.fail(t,
                           "Radiosity count can not be more than direction pool size (count 2nd "
                           "value).");
                break;
            }
            case Keyword::kw_nearest_count: {
                rs.nearestCount = static_cast<int>(r.parseFloat());
                if (rs.nearestCount < 1 || rs.nearestCount > 20)
                    r.fail(t, "Radiosity nearest count must be a value from 1 to 20.");
                if (r.accept(Sym::Comma)) {
                    rs.nearestCountPretrace = static_cast<int>(r.parseFloat());
                    if (rs.nearestCountPretrace < 0 || rs.nearestCountPretrace >= rs.nearestCount)
                        r.fail(t,
                               "Radiosity nearest count for adaptive pretrace must be non-negative "
                               "and smaller than general nearest count.");
                }
                break;
            }
            case Keyword::kw_recursion_limit:
                rs.recursionLimit = static_cast<int>(r.parseFloat());
                if (rs.recursionLimit < 1 || rs.recursionLimit > 20)
                    r.fail(t, "Radiosity recursion limit must be in the range 1 to 20.");
                break;
            case Keyword::kw_save_file:
            case Keyword::kw_load_file:
                // povray 3.7 takes these from the options only.
                r.parseString();
                r.warn(t, fmt::format("In POV-Ray 3.7 and later '{}' has to be specified as an "
                                      "option on the command-line, in an INI file or in a dialog "
                                      "(on some platforms). The '{}' setting here will be ignored!",
                                      t.text, t.text));
                break;
            default:
                r.fail(t, fmt::format("expected a radiosity setting or '}}', found {}",
                                      describeToken(t)));
        }
    }
    if (rs.pretraceEnd > rs.pretraceStart)
        r.fail(start, "Radiosity pretrace end must be smaller than or equal to pretrace start.");
    // povray widens the reuse range when it is narrower than a factor 2,
    // moving the bound that was not given (measured, with its warnings).
    if (rs.minimumReuse > rs.maximumReuse / 2) {
        std::string fix;
        if (minimumGiven && !maximumGiven) {
            rs.maximumReuse = rs.minimumReuse * 2;
            fix = fmt::format(" Increasing maximum_reuse to {:.6f} instead of the default.",
                              rs.maximumReuse);
        } else if (maximumGiven && !minimumGiven) {
            rs.minimumReuse = rs.maximumReuse / 2;
            fix = fmt::format(" Decreasing minimum_reuse to {:.6f} instead of the default.",
                              rs.minimumReuse);
        }
        r.warn(start,
               "Radiosity maximum_reuse should be significantly larger than minimum_reuse." + fix);
    }
    c.scene.globals.radiosity = rs;
}

void parseObjectRadiosity(BuildContext& c, scene::Object& obj) {
    Reader& r = c.reader;
    r.next();  // 'radiosity'
    r.expect(Sym::LBrace, "'{' after 'radiosity'");
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        const Token t = r.next();
        if (!t.is(Keyword::kw_importance))
            r.fail(t, fmt::format("expected 'importance' or '}}', found {}", describeToken(t)));
        const double importance = r.parseFloat();
        if (importance <= 0 || importance > 1)
            r.fail(t, "Radiosity importance must be greater than 0.0 and at most 1.0.");
        obj.radiosityImportance = importance;
    }
}

}  // namespace frameray::sdl
