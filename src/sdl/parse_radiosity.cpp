// radiosity { } in global_settings and in objects. Values are checked
// with povray 3.7's ranges and messages (measured); the settings go to
// scene::RadiositySettings, the object's to scene::Object.
#include <fmt/format.h>

#include <algorithm>

#include "sdl/interpreter.h"

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

void Interpreter::parseRadiositySettings(const Token& start) {
    expect(Sym::LBrace, "'{' after 'radiosity'");
    scene::RadiositySettings r =
        scene_.globals.radiosity ? *scene_.globals.radiosity : scene::RadiositySettings{};
    bool minimumGiven = false, maximumGiven = false;
    auto checked = [&](const Token& at, double v, const RangeCheck& check) {
        if (check.message[0] && !check.accepts(v)) fail(at, check.message);
        return v;
    };
    for (;;) {
        if (accept(Sym::RBrace)) break;
        const Token t = next();
        if (const auto* f = std::find_if(std::begin(kFloatSettings), std::end(kFloatSettings),
                                         [&](const FloatSetting& s) { return t.is(s.kw); });
            f != std::end(kFloatSettings)) {
            r.*(f->member) = checked(t, parseFloat(), f->check);
            minimumGiven |= t.is(Keyword::kw_minimum_reuse);
            maximumGiven |= t.is(Keyword::kw_maximum_reuse);
            continue;
        }
        if (const auto* b = std::find_if(std::begin(kBoolSettings), std::end(kBoolSettings),
                                         [&](const BoolSetting& s) { return t.is(s.kw); });
            b != std::end(kBoolSettings)) {
            r.*(b->member) = parseOptionalBool();
            continue;
        }
        switch (t.kw) {
            case Keyword::kw_count: {
                r.count = static_cast<int>(
                    checked(t, parseFloat(),
                            {0.0, kHuge, true, "Radiosity count must be a positive number."}));
                if (accept(Sym::Comma))
                    r.directionPool = static_cast<int>(checked(
                        t, parseFloat(),
                        {0.0, kHuge, true, "Radiosity direction pool size must be positive."}));
                if (r.count > r.directionPool)
                    fail(t,
                         "Radiosity count can not be more than direction pool size (count 2nd "
                         "value).");
                break;
            }
            case Keyword::kw_nearest_count: {
                r.nearestCount = static_cast<int>(parseFloat());
                if (r.nearestCount < 1 || r.nearestCount > 20)
                    fail(t, "Radiosity nearest count must be a value from 1 to 20.");
                if (accept(Sym::Comma)) {
                    r.nearestCountPretrace = static_cast<int>(parseFloat());
                    if (r.nearestCountPretrace < 0 || r.nearestCountPretrace >= r.nearestCount)
                        fail(t,
                             "Radiosity nearest count for adaptive pretrace must be non-negative "
                             "and smaller than general nearest count.");
                }
                break;
            }
            case Keyword::kw_recursion_limit:
                r.recursionLimit = static_cast<int>(parseFloat());
                if (r.recursionLimit < 1 || r.recursionLimit > 20)
                    fail(t, "Radiosity recursion limit must be in the range 1 to 20.");
                break;
            case Keyword::kw_save_file:
            case Keyword::kw_load_file:
                // povray 3.7 takes these from the options only.
                parseString();
                warn(t, fmt::format("In POV-Ray 3.7 and later '{}' has to be specified as an "
                                    "option on the command-line, in an INI file or in a dialog "
                                    "(on some platforms). The '{}' setting here will be ignored!",
                                    t.text, t.text));
                break;
            default:
                fail(t, fmt::format("expected a radiosity setting or '}}', found {}",
                                    describeToken(t)));
        }
    }
    if (r.pretraceEnd > r.pretraceStart)
        fail(start, "Radiosity pretrace end must be smaller than or equal to pretrace start.");
    // povray widens the reuse range when it is narrower than a factor 2,
    // moving the bound that was not given (measured, with its warnings).
    if (r.minimumReuse > r.maximumReuse / 2) {
        std::string fix;
        if (minimumGiven && !maximumGiven) {
            r.maximumReuse = r.minimumReuse * 2;
            fix = fmt::format(" Increasing maximum_reuse to {:.6f} instead of the default.",
                              r.maximumReuse);
        } else if (maximumGiven && !minimumGiven) {
            r.minimumReuse = r.maximumReuse / 2;
            fix = fmt::format(" Decreasing minimum_reuse to {:.6f} instead of the default.",
                              r.minimumReuse);
        }
        warn(start,
             "Radiosity maximum_reuse should be significantly larger than minimum_reuse." + fix);
    }
    scene_.globals.radiosity = r;
}

void Interpreter::parseObjectRadiosity(scene::Object& obj) {
    next();  // 'radiosity'
    expect(Sym::LBrace, "'{' after 'radiosity'");
    for (;;) {
        if (accept(Sym::RBrace)) break;
        const Token t = next();
        if (!t.is(Keyword::kw_importance))
            fail(t, fmt::format("expected 'importance' or '}}', found {}", describeToken(t)));
        const double importance = parseFloat();
        if (importance <= 0 || importance > 1)
            fail(t, "Radiosity importance must be greater than 0.0 and at most 1.0.");
        obj.radiosityImportance = importance;
    }
}

}  // namespace frameray::sdl
