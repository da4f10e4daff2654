#include "render/atmosphere.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "util/hash.h"

namespace frameray::render {

namespace {

// POV-Ray's EPSILON, used by its fog and rainbow tests.
constexpr double kEpsilon = 1e-10;

// What a layer lets through: its colour where it filters, plus what it
// transmits unchanged.
RGB passedThrough(const Color& c) {
    return c.rgb * c.filter + RGB(c.transmit);
}

// Sky sphere and background from language version 3.7 on: the background
// is one more layer below the sky's pigments, and the layers combine as a
// layered texture does. Each layer adds its colour weighted by its opacity
// (1 - filter - transmit) and by what the layers above let through.
// The background's opacity ignores its filter but not its transmit, even
// without an alpha channel (measured with povray 3.7.0.10: background
// { rgbt <c, 0.5> } renders 0.5 c, background { rgbf <c, 0.5> } renders c,
// a sky layer rgbf <c, 0.7> over black renders 0.3 c).
Color layeredSky(const scene::Scene& scene, const Vec3& direction) {
    RGB color;
    RGB through(1.0);
    if (const auto& sky = scene.atmosphere.skySphere) {
        const Vec3 p = sky->transform.inversePoint(direction);
        for (auto layer = sky->pigments.rbegin(); layer != sky->pigments.rend(); ++layer) {
            const Color c = (*layer)->at(p);
            color += c.rgb * (1.0 - c.filter - c.transmit) * through * sky->emission;
            through *= passedThrough(c);
        }
    }
    const Color& bg = scene.background;
    color += bg.rgb * (1.0 - bg.transmit) * through;
    through *= passedThrough(bg);
    return Color(color, 0.0, std::min(1.0, std::fabs(grey(through))));
}

// Sky sphere and background before version 3.7: the background colour,
// filter and transmit as given, seen through the sky's layers, which
// attenuate each other by their combined filter and transmit.
Color legacySky(const scene::Scene& scene, const Vec3& direction) {
    const Color& bg = scene.background;
    const auto& sky = scene.atmosphere.skySphere;
    if (!sky || sky->pigments.empty()) return bg;
    RGB color;
    Color combined(RGB(1.0), 1.0, 1.0);
    double remaining = 1.0;
    const Vec3 p = sky->transform.inversePoint(direction);
    for (auto layer = sky->pigments.rbegin(); layer != sky->pigments.rend(); ++layer) {
        const Color c = (*layer)->at(p);
        color += c.rgb * (remaining * (1.0 - c.filter - c.transmit));
        combined =
            Color(combined.rgb * c.rgb, combined.filter * c.filter, combined.transmit * c.transmit);
        remaining = std::fabs(combined.filter) + std::fabs(combined.transmit);
    }
    color *= sky->emission;
    const RGB behind = combined.rgb * combined.filter + RGB(combined.transmit);
    return Color(color + bg.rgb * behind, bg.filter * combined.filter,
                 bg.transmit * combined.transmit);
}

// A number in [0, 1) that depends only on the ray direction. POV-Ray
// jitters rainbows with a per-thread random stream, so its own images vary
// between runs; frameray keeps every pixel a function of its ray.
double directionNoise(const Vec3& d) {
    uint64_t h = 0x9E3779B97F4A7C15ull;
    for (const double v : {d.x, d.y, d.z}) h = splitmix64(h ^ std::bit_cast<uint64_t>(v));
    return unitFromHash(h);
}

// The fraction of ground fog density averaged over the segment between
// heights `start` and `end` (in units of fog_alt above fog_offset): the
// density is 1 below 0 and 1 / (1 + h^2) above, whose integral is atan.
double groundFogDensity(double start, double end) {
    if (start <= 0.0) return end <= 0.0 ? 1.0 : (std::atan(end) - start) / (end - start);
    if (end <= 0.0) return (std::atan(start) - end) / (start - end);
    const double delta = start - end;
    if (std::fabs(delta) > kEpsilon) return (std::atan(start) - std::atan(end)) / delta;
    return 1.0 / (start * start + 1.0);
}

// The factor a fog's turbulence puts on its optical depth, measured from
// povray 3.7 renders (constant and ground fog alike): the scalar turbulence
// T at the ray's midpoint scaled by the turbulence amount, s = min(1,
// turb_depth * T), and the factor 1 - exp(-depth / distance) * s (checked for
// depth / distance from 0.4 to 2, turb_depth -0.5 to 1).
double fogTurbulenceFactor(const scene::Fog& fog, const Vec3& origin, const Vec3& direction,
                           double depth) {
    if (!fog.turbulence) return 1.0;
    const Vec3 mid = origin + direction * (0.5 * depth);
    const double t = scene::turbulence(mul(mid, fog.turbulence->amount), *fog.turbulence,
                                       scene::NoiseGenerator::RangeCorrected);
    const double s = std::min(1.0, fog.turbulenceDepth * t);
    return 1.0 - std::exp(-depth / fog.distance) * s;
}

// Transmittance of one fog over `depth` along the ray.
double fogTransmittance(const scene::Fog& fog, const Vec3& origin, const Vec3& direction,
                        double depth) {
    const double turb = fogTurbulenceFactor(fog, origin, direction, depth);
    if (fog.kind == scene::Fog::Kind::Constant) return std::exp(-depth * turb / fog.distance);
    const Vec3 end = origin + direction * depth;
    const double start = (dot(origin, fog.up) - fog.offset) / fog.altitude;
    const double stop = (dot(end, fog.up) - fog.offset) / fog.altitude;
    return std::exp(-depth * turb * groundFogDensity(start, stop) / fog.distance);
}

}  // namespace

AtmosphereView::AtmosphereView(const scene::Scene& scene, bool volumetric)
    : scene_(scene),
      volumetric_(volumetric &&
                  (!scene.atmosphere.fogs.empty() || !scene.atmosphere.rainbows.empty())) {}

Color AtmosphereView::sky(const Vec3& unitDirection) const {
    return scene_.renderVersion() < 3.7 - 1e-9 ? legacySky(scene_, unitDirection)
                                               : layeredSky(scene_, unitDirection);
}

Color AtmosphereView::throughRainbows(const Vec3& d, double depth, const Color& seen) const {
    RGB sum;
    double filter = 1.0, transmit = 1.0;
    int count = 0;
    for (const scene::Rainbow& rainbow : scene_.atmosphere.rainbows) {
        if (!rainbow.colorMap || rainbow.distance == 0.0 || rainbow.width == 0.0) continue;
        // The ray's angle from the rainbow's up vector, in the plane
        // across the antisolar direction: the arc is cut off beyond arcAngle.
        const double x = dot(d, rainbow.right);
        double y = dot(d, rainbow.up);
        const double l = x * x + y * y;
        if (l > 0.0) y /= std::sqrt(l);
        const double arc = std::fabs(std::acos(y));
        if (!(arc <= rainbow.arcAngle)) continue;
        const double cosAntisolar = dot(d, rainbow.antisolar);
        if (cosAntisolar < 0.0) continue;
        double index = (std::acos(cosAntisolar) - rainbow.bandStart) / rainbow.width;
        if (rainbow.jitter > 0.0) index += (2.0 * directionNoise(d) - 1.0) * rainbow.jitter;
        if (!(index >= 0.0 && index <= 1.0 - kEpsilon)) continue;
        const Color band = rainbow.colorMap->at(index);
        double fade = 0.0;
        if (rainbow.falloffWidth > 0.0 && arc > rainbow.falloffAngle) {
            fade = (arc - rainbow.falloffAngle) / rainbow.falloffWidth;
            fade = (3.0 - 2.0 * fade) * fade * fade;
        }
        // How much of what is behind stays visible: distance haze, at
        // least the band's transmit, more where the arc fades out.
        double keep = std::exp(-depth / rainbow.distance);
        keep = std::max(keep, fade * (1.0 - band.transmit) + band.transmit);
        const double cover = 1.0 - keep;
        const double f = band.filter * cover;
        const RGB tint = RGB(1.0 - f) + band.rgb * f;
        sum += seen.rgb * tint * keep + band.rgb * cover;
        filter *= keep * band.filter;
        transmit *= keep * band.transmit;
        ++count;
    }
    if (count == 0) return seen;
    return Color(sum * (1.0 / count), seen.filter * filter, seen.transmit * transmit);
}

Color AtmosphereView::throughFogs(const Vec3& origin, const Vec3& d, double depth,
                                  const Color& seen) const {
    RGB attenuation(1.0);
    RGB added;
    for (const scene::Fog& fog : scene_.atmosphere.fogs) {
        if (!(std::fabs(fog.distance) > kEpsilon)) continue;
        // fog transmit: the least fraction of what is behind that stays.
        const double keep = std::max(fogTransmittance(fog, origin, d, depth), fog.color.transmit);
        // fog filter: what stays is tinted by the fog colour.
        attenuation *= (RGB(1.0 - fog.color.filter) + fog.color.rgb * fog.color.filter) * keep;
        added += fog.color.rgb * (1.0 - keep);
    }
    return Color(added + attenuation * seen.rgb, seen.filter, seen.transmit * grey(attenuation));
}

double fogLightTransmittance(const scene::Scene& scene, const Vec3& origin,
                             const Vec3& unitDirection, double depth,
                             std::span<const std::pair<Vec3, double>> without) {
    double keep = 1.0;
    for (const scene::Fog& fog : scene.atmosphere.fogs) {
        if (!(std::fabs(fog.distance) > kEpsilon)) continue;
        double t = fogTransmittance(fog, origin, unitDirection, depth);
        for (const auto& [from, length] : without) {
            const double inside = fogTransmittance(fog, from, unitDirection, length);
            if (inside > 0) t /= inside;
        }
        keep *= std::max(std::min(t, 1.0), fog.color.transmit);
    }
    return keep;
}

Color AtmosphereView::miss(const scene::Ray& ray) const {
    const Vec3 d = normalize(ray.direction);
    Color c = sky(d);
    if (!volumetric_) return c;
    c = throughRainbows(d, kMissDepth, c);
    return throughFogs(ray.origin, d, kMissDepth, c);
}

Color AtmosphereView::along(const scene::Ray& ray, double t, const Color& seen) const {
    if (!volumetric_) return seen;
    const double scale = length(ray.direction);
    const Vec3 d = ray.direction * (1.0 / scale);
    const double depth = t * scale;
    return throughFogs(ray.origin, d, depth, throughRainbows(d, depth, seen));
}

}  // namespace frameray::render
