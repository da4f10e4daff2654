// finish { } and interior { }: how a surface lights, mirrors and lets
// light through, and what fills the object behind it.
#include <fmt/format.h>

#include "sdl/interpreter.h"

namespace frameray::sdl {

void Interpreter::parseReflectionBlock(scene::Finish& f) {
    // reflection { [min,] max [fresnel B] [falloff F] [exponent E] [metallic M] }
    scene::Reflection& r = f.reflection;
    const Color first = parseColor();
    bool twoValues = false;
    if (accept(Sym::Comma)) {
        r.min = first.rgb;
        r.max = parseColor().rgb;
        twoValues = true;
    } else {
        r.min = r.max = first.rgb;
    }
    for (;;) {
        if (accept(Sym::RBrace)) break;
        const Token t = next();
        switch (t.kw) {
            case Keyword::kw_fresnel:
                r.fresnel = parseOptionalFloat(1.0) != 0;
                break;
            case Keyword::kw_falloff:
                r.falloff = parseFloat();
                break;
            case Keyword::kw_exponent:
                r.exponent = parseFloat();
                break;
            case Keyword::kw_metallic:
                r.metallic = parseOptionalFloat(1.0);
                break;
            case Keyword::kw_conserve_energy:
                f.conserveEnergy = parseOptionalFloat(1.0) != 0;
                break;
            default:
                fail(t,
                     fmt::format("expected a reflection item or '}}', found {}", describeToken(t)));
        }
    }
    // povray: one value with fresnel is the maximum, reached at grazing
    // angles; the minimum is then 0 (measured: `reflection {0.8 fresnel}`
    // reflects 0.8 * 0.04 head-on at ior 1.5).
    if (!twoValues && r.fresnel) r.min = RGB(0.0);
}

void Interpreter::parseIridescence(scene::Finish& f) {
    expect(Sym::LBrace, "'{' after 'irid'");
    f.irid.amount = parseFloat();
    for (;;) {
        if (accept(Sym::RBrace)) return;
        const Token t = next();
        switch (t.kw) {
            case Keyword::kw_thickness:
                f.irid.thickness = parseFloat();
                break;
            case Keyword::kw_turbulence:
                f.irid.turbulence = parseFloat();
                break;
            default:
                fail(t, fmt::format("expected an irid item or '}}', found {}", describeToken(t)));
        }
    }
}

void Interpreter::parseFinishItems(scene::Finish& f) {
    // Which values of this block were given as albedos; they are converted
    // to povray's coefficients when the block closes, with the block's
    // final brilliance, roughness and phong_size (measured: the order of
    // the items does not matter, and a finish that starts from a declared
    // one does not convert its values again).
    scene::FinishAlbedo albedo;
    for (;;) {
        if (accept(Sym::RBrace)) {
            scene::applyAlbedo(f, albedo);
            return;
        }
        const Token t = next();
        switch (t.kw) {
            case Keyword::kw_ambient:
                f.ambient = parseColor().rgb;
                break;
            case Keyword::kw_emission:
                f.emission = parseColor().rgb;
                break;
            case Keyword::kw_diffuse:
                // diffuse [albedo] A [, B]: B lights the surface from lights
                // on its far side (povray 3.7, measured: B * cos^brilliance).
                albedo.diffuse = accept(Keyword::kw_albedo);
                f.diffuse = parseFloat();
                f.diffuseBack = accept(Sym::Comma) ? parseFloat() : 0.0;
                break;
            case Keyword::kw_brilliance:
                f.brilliance = parseFloat();
                break;
            case Keyword::kw_crand:
                f.crand = parseFloat();
                break;
            case Keyword::kw_phong:
                albedo.phong = accept(Keyword::kw_albedo);
                f.phong = parseFloat();
                break;
            case Keyword::kw_phong_size:
                f.phongSize = parseFloat();
                break;
            case Keyword::kw_specular:
                albedo.specular = accept(Keyword::kw_albedo);
                f.specular = parseFloat();
                break;
            case Keyword::kw_roughness:
                f.roughness = parseFloat();
                break;
            case Keyword::kw_metallic:
                f.metallic = parseOptionalFloat(1.0);
                break;
            case Keyword::kw_reflection:
                if (accept(Sym::LBrace)) {
                    parseReflectionBlock(f);
                } else {
                    // The old form: one colour, constant at every angle.
                    f.reflection.min = f.reflection.max = parseColor().rgb;
                }
                break;
            case Keyword::kw_reflection_exponent:
                f.reflection.exponent = parseFloat();
                break;
            case Keyword::kw_conserve_energy:
                f.conserveEnergy = parseOptionalFloat(1.0) != 0;
                break;
            case Keyword::kw_irid:
                parseIridescence(f);
                break;
            case Keyword::kw_refraction:
                // 2.0: refraction 1 turned bending on; 3.x bends whenever
                // the ior differs from 1, so only the value is read.
                parseFloat();
                break;
            case Keyword::kw_ior:
                f.legacyIor = parseFloat();
                break;
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    unsupported(t, fmt::format("'{}' in finish", t.text));
                fail(t, fmt::format("expected a finish item or '}}', found {}", describeToken(t)));
        }
    }
}

FinishPtr Interpreter::parseFinish(const scene::Finish* base) {
    next();  // finish
    expect(Sym::LBrace, "'{' after 'finish'");
    scene::Finish f = base ? *base : defaultTexture_.finish;
    const Token t = peek();
    if (t.isIdentifier()) {
        next();
        const Value v = identifierValue(t);
        const auto* fp = std::get_if<FinishPtr>(&v);
        if (!fp) fail(t, fmt::format("'{}' is a {}, not a finish", t.text, valueKindName(v)));
        f = **fp;
    }
    parseFinishItems(f);
    return std::make_shared<const scene::Finish>(f);
}

InteriorPtr Interpreter::parseInterior(const scene::Interior* base) {
    next();  // interior
    expect(Sym::LBrace, "'{' after 'interior'");
    scene::Interior in = base ? *base : scene::Interior{};
    const Token first = peek();
    if (first.isIdentifier()) {
        next();
        const Value v = identifierValue(first);
        const auto* ip = std::get_if<InteriorPtr>(&v);
        if (!ip)
            fail(first, fmt::format("'{}' is a {}, not an interior", first.text, valueKindName(v)));
        in = **ip;
    }
    for (;;) {
        if (accept(Sym::RBrace)) break;
        if (peek().is(Keyword::kw_media)) {
            in.media.push_back(parseMedia());
            continue;
        }
        const Token t = next();
        switch (t.kw) {
            case Keyword::kw_ior:
                in.ior = parseFloat();
                break;
            case Keyword::kw_dispersion:
                in.dispersion = parseFloat();
                break;
            case Keyword::kw_dispersion_samples:
                in.dispersionSamples = static_cast<int>(parseFloat());
                break;
            case Keyword::kw_fade_distance:
                in.fadeDistance = parseFloat();
                break;
            case Keyword::kw_fade_power:
                in.fadePower = parseFloat();
                break;
            case Keyword::kw_fade_color:
            case Keyword::kw_fade_colour:
                in.fadeColor = parseColor().rgb;
                break;
            case Keyword::kw_caustics:
                in.caustics = parseFloat();
                break;
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    unsupported(t, fmt::format("'{}' in interior", t.text));
                fail(t,
                     fmt::format("expected an interior item or '}}', found {}", describeToken(t)));
        }
    }
    if (in.dispersionSamples < 2) in.dispersionSamples = 2;
    return std::make_shared<const scene::Interior>(in);
}

}  // namespace frameray::sdl
