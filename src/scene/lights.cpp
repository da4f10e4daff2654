#include "scene/lights.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "scene/object.h"

namespace frameray::scene {

double smoothEdge(double low, double high, double x) {
    if (x <= low) return 0.0;
    if (x >= high) return 1.0;
    const double s = (x - low) / (high - low);
    return (3.0 - 2.0 * s) * s * s;
}

Vec3 AreaLight::gridOffset(double i, double j, const Vec3& a1, const Vec3& a2) const {
    // Position of the sample across each axis, in [-1/2, 1/2].
    double u = size1 > 1 ? i / (size1 - 1) - 0.5 : 0.0;
    double v = size2 > 1 ? j / (size2 - 1) - 0.5 : 0.0;
    if (circular) {
        // The square grid is squeezed into the inscribed disc: each square
        // ring of the grid becomes a circle of the same half width (so a
        // point keeps its direction and max(|u|, |v|) becomes its radius).
        // The tiny shift keeps the centre sample off the 0/0 case, as
        // povray's own samples are (measured: its disc is not centred to
        // within 1e-3 of the axes).
        u += 0.001;
        v += 0.001;
        const double r = std::sqrt(u * u + v * v);  // u, v are small: no overflow
        const double scale = std::max(std::fabs(u), std::fabs(v)) / r;
        u *= scale;
        v *= scale;
    }
    return a1 * u + a2 * v;
}

void Light::transformBy(const Transform& t) {
    position = t.point(position);
    pointAt = t.point(pointAt);
    area.axis1 = t.direction(area.axis1);
    area.axis2 = t.direction(area.axis2);
    auto moved = [&](const std::shared_ptr<const Object>& obj) -> std::shared_ptr<const Object> {
        if (!obj) return obj;
        auto copy = std::make_shared<Object>(*obj);
        copy->transformBy(t);
        return copy;
    };
    looksLike = moved(looksLike);
    projectedThrough = moved(projectedThrough);
}

Vec3 Light::axis() const {
    const Vec3 d = pointAt - position;
    const double len = length(d);
    return len > 0 ? d / len : Vec3(0, 0, 1);
}

double Light::attenuation(const Vec3& p, double distance) const {
    double a = 1.0;
    switch (kind) {
        case LightKind::Point:
            break;
        case LightKind::Spot: {
            // Cosine of the angle between the spot axis and the light's
            // way to p; measured against povray 3.7: cos^tightness times
            // the cubic edge from the falloff cone (0) to the radius cone.
            const Vec3 out = p - position;
            const double len = length(out);
            // A parallel spotlight's rays all run along the axis: no cone,
            // but nothing behind the light's plane is lit (measured).
            const double c = parallel  ? (dot(out, axis()) > 0 ? 1.0 : 0.0)
                             : len > 0 ? dot(out / len, axis())
                                       : 1.0;
            if (c <= 0) return 0.0;
            if (tightness != 0) a *= std::pow(c, tightness);
            const double toRad = std::numbers::pi / 180.0;
            const double cosRadius = std::cos(radius * toRad),
                         cosFalloff = std::cos(falloff * toRad);
            if (radius > 0) a *= smoothEdge(cosFalloff, cosRadius, c);
            break;
        }
        case LightKind::Cylinder: {
            const Vec3 ax = axis();
            const Vec3 rel = p - position;
            const double along = dot(rel, ax);
            if (along <= 0) return 0.0;  // behind the light
            const double off = length(rel - ax * along);
            if (off >= falloff) return 0.0;
            // Measured against povray 3.7: (1 - d/falloff)^tightness, times
            // the cubic edge from the falloff (0) to the radius (1).
            const double d = 1.0 - off / falloff;
            if (tightness != 0) a *= std::pow(d, tightness);
            if (radius > 0 && off > radius) a *= smoothEdge(0.0, 1.0 - radius / falloff, d);
            break;
        }
    }
    if (fadeDistance > 0 && fadePower > 0)
        a *= 2.0 / (1.0 + std::pow(distance / fadeDistance, fadePower));
    return a;
}

}  // namespace frameray::scene
