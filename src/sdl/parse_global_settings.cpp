// global_settings { }: the scene-wide settings (assumed_gamma,
// max_trace_level, adc_bailout, ambient_light, irid_wavelength, charset...).
#include <fmt/format.h>

#include <algorithm>

#include "sdl/builders.h"

namespace frameray::sdl {

void parseGlobalSettings(BuildContext& c) {
    Reader& r = c.reader;
    r.next();
    r.expect(Sym::LBrace, "'{' after 'global_settings'");
    auto& g = c.scene.globals;
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        const Token t = r.next();
        switch (t.kw) {
            case Keyword::kw_assumed_gamma:
                g.assumedGamma = r.parseFloat();
                g.assumedGammaSet = true;
                r.setAssumedGamma(g.assumedGamma);  // sRGB colours need it
                break;
            case Keyword::kw_max_trace_level:
                g.maxTraceLevel = static_cast<int>(r.parseFloat());
                break;
            case Keyword::kw_adc_bailout:
                g.adcBailout = r.parseFloat();
                break;
            case Keyword::kw_ambient_light:
                g.ambientLight = r.parseColor().rgb;
                break;
            case Keyword::kw_irid_wavelength:
                g.iridWavelength = r.parseColor().rgb;
                break;
            case Keyword::kw_number_of_waves: {
                // Whole sources (2.7 is 2); below 1 is 1, with povray's
                // warning (measured).
                const double n = r.parseFloat();
                if (!(n < 1e6)) r.fail(t, "number_of_waves must be below 1000000");
                int count = n < 1 ? 0 : static_cast<int>(n);
                if (count < 1) {
                    r.warn(t,
                           "Illegal Value: number_of_waves must be greater than 0. Changed "
                           "to 1.");
                    count = 1;
                }
                r.setNumberOfWaves(count);
                break;
            }
            case Keyword::kw_noise_generator:
                r.setNoiseGenerator(parseNoiseGenerator(c, t), t);
                break;
            case Keyword::kw_charset: {
                static constexpr std::pair<Keyword, scene::TextCharset> kCharsets[] = {
                    {Keyword::kw_ascii, scene::TextCharset::Ascii},
                    {Keyword::kw_utf8, scene::TextCharset::Utf8},
                    {Keyword::kw_sys, scene::TextCharset::System}};
                const Token charset = r.next();
                const auto* found =
                    std::find_if(std::begin(kCharsets), std::end(kCharsets),
                                 [&](const auto& entry) { return charset.is(entry.first); });
                if (found == std::end(kCharsets))
                    r.fail(charset,
                           fmt::format("expected a charset type (ascii, utf8 or sys), found {}",
                                       describeToken(charset)));
                c.textCharset = found->second;
                break;
            }
            case Keyword::kw_radiosity:
                parseRadiositySettings(c, t);
                break;
            case Keyword::kw_hf_gray_16:
                r.parseOptionalBool();
                break;
            case Keyword::kw_mm_per_unit:
                g.mmPerUnit = r.parseFloat();
                break;
            case Keyword::kw_subsurface: {
                // A second block keeps what the first set.
                if (!g.subsurface) g.subsurface.emplace();
                r.expect(Sym::LBrace, "'{' after 'subsurface'");
                for (;;) {
                    if (r.accept(Sym::RBrace)) break;
                    const Token item = r.next();
                    if (item.is(Keyword::kw_samples)) {
                        g.subsurface->samplesDiffuse = static_cast<int>(r.parseFloat());
                        r.accept(Sym::Comma);
                        g.subsurface->samplesSingle = static_cast<int>(r.parseFloat());
                    } else if (item.is(Keyword::kw_radiosity)) {
                        g.subsurface->radiosity = r.parseFloat() != 0;
                        if (g.subsurface->radiosity)
                            r.unsupported(item, "radiosity light under a subsurface finish");
                    } else {
                        r.fail(item, fmt::format("expected samples, radiosity or '}}' in "
                                                 "subsurface, found {}",
                                                 describeToken(item)));
                    }
                }
                break;
            }
            case Keyword::kw_photons:
                // A second block replaces the first's values item by item.
                if (!g.photons) g.photons.emplace();
                parseGlobalPhotons(c, *g.photons);
                break;
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    r.unsupported(t, fmt::format("'{}' in global_settings", t.text));
                r.fail(t, fmt::format("expected a global setting or '}}', found {}",
                                      describeToken(t)));
        }
    }
}

}  // namespace frameray::sdl
