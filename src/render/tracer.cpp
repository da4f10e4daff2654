#include "render/tracer.h"

#include <algorithm>
#include <cmath>

namespace frameray::render {

namespace {

const scene::Texture& defaultTexture() {
    static const scene::Texture kDefault;  // immutable: black pigment, default finish
    return kDefault;
}

// Distance below which a secondary ray leaving the surface point p (found
// along `ray`) ignores crossings, so it does not re-hit its own surface.
// p = origin + t * direction is computed in double, so its error is a few
// ulps of the largest magnitude involved: of p itself and of the ray's
// origin (a camera far from a surface near the world origin gives |p| ~ 0
// but an error ~ ulp(|origin|)). 1e-9 of that magnitude is ~10^7 ulps:
// far above the rounding error, far below any visible detail, and purely
// relative, so a scene renders the same at any scale
// (tests/stability/scale_all_primitives.pov checks 1e-4 to 1e5).
double selfHitEpsilon(const Vec3& p, const scene::Ray& ray) {
    const Vec3& o = ray.origin;
    const double m = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z), std::fabs(o.x), std::fabs(o.y),
                               std::fabs(o.z)});
    // The floor only keeps the epsilon positive (a scene at the origin).
    return std::max(m * 1e-9, 1e-300);
}

}  // namespace

RGB Tracer::traceCamera(const scene::Ray& ray, RayCounts& counts) const {
    ++counts.camera;
    Hit hit;
    if (!world_.intersect(ray, 0.0, scene::kInfinity, hit)) return atmosphere_.miss(ray).rgb;
    return atmosphere_.along(ray, hit.t, Color(shade(ray, hit, counts))).rgb;
}

RGB Tracer::shade(const scene::Ray& ray, const Hit& hit, RayCounts& counts) const {
    const scene::Object& obj = *hit.object;
    const Vec3 p = ray.at(hit.t);
    const Vec3 viewDir = normalize(ray.direction);
    // The hit primitive (for CSG, the child whose surface was crossed)
    // carries its complete transform and inherited texture.
    Vec3 n = obj.normalAt(p);
    // Shade the side facing the viewer.
    if (dot(n, viewDir) > 0) n = -n;
    if (obj.texture) n = obj.texture->perturbNormal(p, n);

    const scene::Texture& tex = obj.texture ? *obj.texture : defaultTexture();
    const scene::Finish& fin = tex.finish;
    const RGB pigment = tex.pigment->at(tex.transform.inversePoint(p)).rgb;

    RGB color = fin.ambient * pigment * scene_.globals.ambientLight + fin.emission * pigment;

    const Vec3 reflected = viewDir - n * (2 * dot(viewDir, n));
    const double eps = selfHitEpsilon(p, ray);
    for (const scene::Light& light : scene_.lights) {
        Vec3 toLight = light.position - p;
        const double dist = length(toLight);
        if (dist == 0) continue;
        toLight = toLight / dist;
        // A light behind the surface only reaches double_illuminate
        // objects: their far side is lit as if it faced the light.
        Vec3 ln = n;
        double cosIncidence = dot(n, toLight);
        if (cosIncidence <= 0 && obj.doubleIlluminate) {
            ln = -n;
            cosIncidence = -cosIncidence;
        }
        if (cosIncidence <= 0) continue;
        if (!light.shadowless) {
            ++counts.shadow;
            if (world_.occluded({p, toLight}, eps, dist)) continue;
        }
        const RGB lightColor = light.color;
        if (fin.diffuse > 0) {
            const double intensity =
                fin.diffuse * (fin.brilliance == 1.0 ? cosIncidence : std::pow(cosIncidence, fin.brilliance));
            color += lightColor * pigment * intensity;
        }
        if (fin.phong > 0) {
            const double c = dot(reflected, toLight);
            if (c > 0) {
                const RGB tint = fin.metallic ? pigment : RGB(1.0);
                color += lightColor * tint * (fin.phong * std::pow(c, fin.phongSize));
            }
        }
        if (fin.specular > 0) {
            const Vec3 halfway = normalize(toLight - viewDir);
            const double c = dot(halfway, ln);
            if (c > 0) {
                const RGB tint = fin.metallic ? pigment : RGB(1.0);
                color += lightColor * tint * (fin.specular * std::pow(c, 1.0 / fin.roughness));
            }
        }
    }
    return color;
}

}  // namespace frameray::render
