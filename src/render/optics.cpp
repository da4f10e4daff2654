#include "render/optics.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "scene/noise.h"

namespace frameray::render {

double fresnelReflectance(double cosIncidence, double relativeIor) {
    const double c = std::clamp(std::fabs(cosIncidence), 0.0, 1.0);
    const double gSquared = relativeIor * relativeIor + c * c - 1.0;
    if (gSquared <= 0) return 1.0;  // total internal reflection
    const double g = std::sqrt(gSquared);
    const double a = (g - c) / (g + c);
    const double b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    return std::clamp(0.5 * a * a * (1.0 + b * b), 0.0, 1.0);
}

double metallicFresnel(double cosAngle) {
    // A fitted curve of the angle in units of a right angle: 0 at normal
    // incidence, 1 at x = 1 (measured against povray's highlight and
    // reflection tints to 4 significant digits).
    const double x = std::acos(std::clamp(std::fabs(cosAngle), 0.0, 1.0)) / (std::numbers::pi / 2);
    const double d = x - 1.12;
    return std::clamp(0.014567225 / (d * d) - 0.011612903, 0.0, 1.0);
}

RGB metallicTint(double metallic, double cosAngle, const RGB& pigment) {
    if (metallic <= 0) return RGB(1.0);
    const double k = metallic * (1.0 - metallicFresnel(cosAngle));
    return RGB(1.0) + (pigment - RGB(1.0)) * k;
}

RGB reflectance(const scene::Reflection& r, double cosIncidence, double relativeIor,
                const RGB& pigment, const RGB& variationScale) {
    double blend;
    if (r.fresnel)
        blend = fresnelReflectance(cosIncidence, relativeIor);
    else
        blend = std::pow(std::max(0.0, 1.0 - std::fabs(cosIncidence)), r.falloff);
    RGB out = r.min + (r.max - r.min) * variationScale * blend;
    if (r.metallic > 0) out = out * metallicTint(r.metallic, cosIncidence, pigment);
    return out;
}

std::optional<Vec3> refractedDirection(const Vec3& d, const Vec3& n, double eta) {
    const double cosI = -dot(d, n);
    const double k = 1.0 - eta * eta * (1.0 - cosI * cosI);
    if (k < 0) return std::nullopt;
    return normalize(d * eta + n * (eta * cosI - std::sqrt(k)));
}

RGB interiorFade(const scene::Interior& in, double distance) {
    if (!in.fades()) return RGB(1.0);
    const double ratio = distance / in.fadeDistance;
    if (in.fadePower >= 1000) {
        auto channel = [&](double fade) { return std::exp(-ratio * (1.0 - fade)); };
        return {channel(in.fadeColor.r), channel(in.fadeColor.g), channel(in.fadeColor.b)};
    }
    const double a = std::isinf(ratio) ? 0.0 : 1.0 / (1.0 + std::pow(ratio, in.fadePower));
    return in.fadeColor + (RGB(1.0) - in.fadeColor) * a;
}

double iridFilmThickness(const scene::Iridescence& irid, const Vec3& p) {
    if (irid.turbulence == 0) return irid.thickness;
    scene::Turbulence turb;
    turb.octaves = 5;
    const double t = scene::turbulence(p, turb, scene::NoiseGenerator::RangeCorrected);
    return irid.thickness * (1.0 + irid.turbulence * (2.0 * t - 1.0));
}

RGB iridTint(double amount, double thickness, const RGB& wavelength, double cosView,
             double cosLight) {
    const double path = 2.0 * std::numbers::pi * thickness * (cosView + cosLight);
    auto channel = [&](double w) { return 1.0 + amount * std::cos(path / w); };
    return {channel(wavelength.r), channel(wavelength.g), channel(wavelength.b)};
}

double fakeCaustics(const scene::Object& obj, const Vec3& p, const Vec3& dir) {
    if (!obj.interior || obj.interior->caustics == 0) return 1.0;
    const bool usesUv = obj.texture && obj.texture->usesUv();
    Vec3 uv(p.x, p.y, 0);
    Vec3 n = usesUv ? obj.normalAndUvAt(p, uv) : obj.normalAt(p);
    if (dot(n, dir) > 0) n = -n;
    if (obj.texture) {
        const scene::Texture& tex = *obj.texture;
        n = tex.perturbNormal(tex.uvMapping ? uv : p, n, uv);
    }
    const double c = std::fabs(dot(n, normalize(dir)));
    return 1.0 + std::pow(c, 45.0 * obj.interior->caustics);
}

RGB reflectionExponent(const RGB& c, double exponent) {
    if (exponent == 1.0) return c;
    const double e = 1.0 / exponent;
    return {std::pow(std::max(c.r, 0.0), e), std::pow(std::max(c.g, 0.0), e),
            std::pow(std::max(c.b, 0.0), e)};
}

}  // namespace frameray::render
