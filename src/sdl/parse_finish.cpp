// finish { } and interior { }: how a surface lights, mirrors and lets
// light through, and what fills the object behind it.
#include <fmt/format.h>

#include "sdl/builders.h"

namespace frameray::sdl {

static void parseReflectionBlock(BuildContext& c, scene::Finish& f) {
    Reader& r = c.reader;
    // reflection { [min,] max [fresnel B] [falloff F] [exponent E] [metallic M] }
    scene::Reflection& refl = f.reflection;
    const Color first = r.parseColor();
    bool twoValues = false;
    // povray reads a second value with or without a comma before it
    // (measured: `reflection { 0.2 0.8 }` renders as `{ 0.2, 0.8 }`;
    // examples/gamma/gamma_showcase.pov writes `{ 0.0 1.0 fresnel on }`).
    if (r.accept(Sym::Comma) || r.colorFollows()) {
        refl.min = first.rgb;
        refl.max = r.parseColor().rgb;
        twoValues = true;
    } else {
        refl.min = refl.max = first.rgb;
    }
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        const Token t = r.next();
        switch (t.kw) {
            case Keyword::kw_fresnel:
                refl.fresnel = r.parseOptionalFloat(1.0) != 0;
                break;
            case Keyword::kw_falloff:
                refl.falloff = r.parseFloat();
                break;
            case Keyword::kw_exponent:
                refl.exponent = r.parseFloat();
                break;
            case Keyword::kw_metallic:
                refl.metallic = r.parseOptionalFloat(1.0);
                break;
            case Keyword::kw_conserve_energy:
                f.conserveEnergy = r.parseOptionalFloat(1.0) != 0;
                break;
            default:
                r.fail(t, fmt::format("expected a reflection item or '}}', found {}",
                                      describeToken(t)));
        }
    }
    // povray: one value with fresnel is the maximum, reached at grazing
    // angles; the minimum is then 0 (measured: `reflection {0.8 fresnel}`
    // reflects 0.8 * 0.04 head-on at ior 1.5).
    if (!twoValues && refl.fresnel) refl.min = RGB(0.0);
}

static void parseIridescence(BuildContext& c, scene::Finish& f) {
    Reader& r = c.reader;
    r.expect(Sym::LBrace, "'{' after 'irid'");
    f.irid.amount = r.parseFloat();
    for (;;) {
        if (r.accept(Sym::RBrace)) return;
        const Token t = r.next();
        switch (t.kw) {
            case Keyword::kw_thickness:
                f.irid.thickness = r.parseFloat();
                break;
            case Keyword::kw_turbulence:
                f.irid.turbulence = r.parseFloat();
                break;
            default:
                r.fail(t, fmt::format("expected an irid item or '}}', found {}", describeToken(t)));
        }
    }
}

static void parseFinishItems(BuildContext& c, scene::Finish& f) {
    Reader& r = c.reader;
    // Which values of this block were given as albedos; they are converted
    // to povray's coefficients when the block closes, with the block's
    // final brilliance, roughness and phong_size (measured: the order of
    // the items does not matter, and a finish that starts from a declared
    // one does not convert its values again).
    scene::FinishAlbedo albedo;
    for (;;) {
        if (r.accept(Sym::RBrace)) {
            scene::applyAlbedo(f, albedo);
            return;
        }
        const Token t = r.next();
        switch (t.kw) {
            case Keyword::kw_ambient:
                f.ambient = r.parseColor().rgb;
                break;
            case Keyword::kw_emission:
                f.emission = r.parseColor().rgb;
                break;
            case Keyword::kw_diffuse:
                // diffuse [albedo] A [, B]: B lights the surface from lights
                // on its far side (povray 3.7, measured: B * cos^brilliance).
                albedo.diffuse = r.accept(Keyword::kw_albedo);
                f.diffuse = r.parseFloat();
                f.diffuseBack = r.accept(Sym::Comma) ? r.parseFloat() : 0.0;
                break;
            case Keyword::kw_brilliance:
                f.brilliance = r.parseFloat();
                break;
            case Keyword::kw_crand:
                f.crand = r.parseFloat();
                break;
            case Keyword::kw_phong:
                albedo.phong = r.accept(Keyword::kw_albedo);
                f.phong = r.parseFloat();
                break;
            case Keyword::kw_phong_size:
                f.phongSize = r.parseFloat();
                break;
            case Keyword::kw_specular:
                albedo.specular = r.accept(Keyword::kw_albedo);
                f.specular = r.parseFloat();
                break;
            case Keyword::kw_roughness:
                f.roughness = r.parseFloat();
                break;
            case Keyword::kw_metallic:
                f.metallic = r.parseOptionalFloat(1.0);
                break;
            case Keyword::kw_reflection:
                if (r.accept(Sym::LBrace)) {
                    parseReflectionBlock(c, f);
                } else {
                    // The old form: one colour, constant at every angle.
                    f.reflection.min = f.reflection.max = r.parseColor().rgb;
                }
                break;
            case Keyword::kw_reflection_exponent:
                f.reflection.exponent = r.parseFloat();
                break;
            case Keyword::kw_conserve_energy:
                f.conserveEnergy = r.parseOptionalFloat(1.0) != 0;
                break;
            case Keyword::kw_irid:
                parseIridescence(c, f);
                break;
            case Keyword::kw_subsurface:
                r.expect(Sym::LBrace, "'{' after 'subsurface'");
                f.subsurface = true;
                for (;;) {
                    if (r.accept(Sym::RBrace)) break;
                    const Token item = r.next();
                    if (!item.is(Keyword::kw_translucency))
                        r.fail(item, fmt::format("expected translucency or '}}' in subsurface, "
                                                 "found {}",
                                                 describeToken(item)));
                    f.translucency = r.parseColor().rgb;
                }
                break;
            case Keyword::kw_refraction:
                // 2.0: refraction 1 turned bending on; 3.x bends whenever
                // the ior differs from 1, so only the value is read.
                r.parseFloat();
                break;
            case Keyword::kw_ior:
                f.legacyIor = r.parseFloat();
                break;
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    r.unsupported(t, fmt::format("'{}' in finish", t.text));
                r.fail(t,
                       fmt::format("expected a finish item or '}}', found {}", describeToken(t)));
        }
    }
}

FinishPtr parseFinish(BuildContext& c, const scene::Finish* base) {
    Reader& r = c.reader;
    r.next();  // finish
    r.expect(Sym::LBrace, "'{' after 'finish'");
    scene::Finish f = base ? *base : *c.defaultTexture.finish;
    const Token t = r.peek();
    if (t.isIdentifier()) {
        r.next();
        const Value v = r.identifierValue(t);
        const auto* fp = std::get_if<FinishPtr>(&v);
        if (!fp) r.fail(t, fmt::format("'{}' is a {}, not a finish", t.text, valueKindName(v)));
        f = **fp;
    }
    parseFinishItems(c, f);
    return std::make_shared<const scene::Finish>(f);
}

InteriorPtr parseInterior(BuildContext& c, const scene::Interior* base) {
    Reader& r = c.reader;
    r.next();  // interior
    r.expect(Sym::LBrace, "'{' after 'interior'");
    scene::Interior in = base ? *base : scene::Interior{};
    const Token first = r.peek();
    if (first.isIdentifier()) {
        r.next();
        const Value v = r.identifierValue(first);
        const auto* ip = std::get_if<InteriorPtr>(&v);
        if (!ip)
            r.fail(first,
                   fmt::format("'{}' is a {}, not an interior", first.text, valueKindName(v)));
        in = **ip;
    }
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        if (r.peek().is(Keyword::kw_media)) {
            in.media.push_back(parseMedia(c));
            continue;
        }
        const Token t = r.next();
        switch (t.kw) {
            case Keyword::kw_ior:
                in.ior = r.parseFloat();
                break;
            case Keyword::kw_dispersion:
                in.dispersion = r.parseFloat();
                break;
            case Keyword::kw_dispersion_samples:
                in.dispersionSamples = static_cast<int>(r.parseFloat());
                break;
            case Keyword::kw_fade_distance:
                in.fadeDistance = r.parseFloat();
                break;
            case Keyword::kw_fade_power:
                in.fadePower = r.parseFloat();
                break;
            case Keyword::kw_fade_color:
            case Keyword::kw_fade_colour:
                in.fadeColor = r.parseColor().rgb;
                break;
            case Keyword::kw_caustics:
                in.caustics = r.parseFloat();
                break;
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    r.unsupported(t, fmt::format("'{}' in interior", t.text));
                r.fail(t, fmt::format("expected an interior item or '}}', found {}",
                                      describeToken(t)));
        }
    }
    if (in.dispersionSamples < 2) in.dispersionSamples = 2;
    return std::make_shared<const scene::Interior>(in);
}

}  // namespace frameray::sdl
