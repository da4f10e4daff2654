#include "render/lighting.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <vector>

#include "scene/hit_tolerance.h"
#include "scene/object.h"
#include "util/hash.h"

namespace frameray::render {

namespace {

// Area-light jitter is a hash of the surface point and the grid point
// (util/hash.h), the same whatever the thread count or tile order (povray's
// own jitter is random from render to render, so no sequence can match it).
struct GridSampler {
    const World& world;
    const scene::Light& light;
    const Vec3& p;
    double selfHit;
    Vec3 centre;  // the light's centre as seen from p
    Vec3 axis1, axis2;
    uint64_t seed;
    uint64_t& shadowRays;
    std::span<const scene::Interior* const> startInside;

    RGB operator()(int i, int j) const {
        double u = i, v = j;
        if (light.area.jitter) {
            const uint64_t h =
                fmix64(seed ^ fmix64(static_cast<uint64_t>(i) * 0x9E3779B97F4A7C15ULL +
                                     static_cast<uint64_t>(j)));
            u += unitFromHash(h) - 0.5;
            v += unitFromHash(fmix64(h)) - 0.5;
        }
        const Vec3 target = centre + light.area.gridOffset(u, v, axis1, axis2);
        Vec3 dir = target - p;
        const double dist = length(dir);
        if (dist == 0) return light.color;
        dir = dir / dist;
        ++shadowRays;
        // The ray stops short of the light by the self-hit margin: a light
        // placed on a surface lights the room, as in povray (the Cornell
        // box's lamps sit in the ceiling's plane).
        return light.color *
               world.shadowFilter({p, dir}, selfHit, dist - selfHit, selfHit, &light, startInside);
    }
};

}  // namespace

RGB subdivideAreaGrid(int size1, int size2, int adaptive,
                      const std::function<RGB(int, int)>& sample) {
    const size_t count = static_cast<size_t>(size1) * static_cast<size_t>(size2);
    // Each grid point is traced at most once; blocks share their corners.
    thread_local std::vector<RGB> cache;
    thread_local std::vector<unsigned char> known;
    cache.resize(count);
    known.assign(count, 0);
    auto at = [&](int i, int j) -> const RGB& {
        const size_t k =
            static_cast<size_t>(j) * static_cast<size_t>(size1) + static_cast<size_t>(i);
        if (!known[k]) {
            cache[k] = sample(i, j);
            known[k] = 1;
        }
        return cache[k];
    };
    // Recursion depth is the log2 of the grid size: small.
    auto block = [&](auto&& self, int u1, int v1, int u2, int v2, int level) -> RGB {
        const RGB c00 = at(u1, v1), c10 = at(u2, v1), c01 = at(u1, v2), c11 = at(u2, v2);
        const bool splittable = u2 - u1 > 1 || v2 - v1 > 1;
        if (splittable && (level < adaptive || summedDifference(c00, c10) > 0.1 ||
                           summedDifference(c10, c11) > 0.1 || summedDifference(c11, c01) > 0.1 ||
                           summedDifference(c01, c00) > 0.1)) {
            // Halves share the middle point when the span is even;
            // an odd span splits into two disjoint halves (measured:
            // povray weights a 4-point row uniformly, a 5-point row 1:2:2:2:1).
            const int um = (u1 + u2) / 2, vm = (v1 + v2) / 2;
            const int uh = (u2 - u1) % 2 ? um + 1 : um, vh = (v2 - v1) % 2 ? vm + 1 : vm;
            RGB sum = self(self, u1, v1, um, vm, level + 1);
            sum += self(self, uh, v1, u2, vm, level + 1);
            sum += self(self, u1, vh, um, v2, level + 1);
            sum += self(self, uh, vh, u2, v2, level + 1);
            return sum * 0.25;
        }
        return (c00 + c10 + c01 + c11) * 0.25;
    };
    return block(block, 0, 0, size1 - 1, size2 - 1, 0);
}

LightsFor::LightsFor(const std::vector<scene::Light>& scene, const scene::Object& primitive) {
    const scene::LightGroup* group = primitive.lightGroup.get();
    if (!group) {
        first_ = scene;
        return;
    }
    if (group->globalLights) first_ = scene;
    second_ = group->lights;
}

bool pathToLight(const scene::Light& light, const Vec3& p, LightPath& path) {
    if (light.parallel || light.kind == scene::LightKind::Cylinder) {
        // Light travels along the axis; the way back to it is the reverse
        // axis, up to the plane through the light across the axis.
        path.toLight = -light.axis();
        path.distance = dot(light.position - p, path.toLight);
        if (light.kind == scene::LightKind::Cylinder && path.distance <= 0) return false;
        if (path.distance <= 0) path.distance = scene::kInfinity;
        return true;
    }
    const Vec3 d = light.position - p;
    path.distance = length(d);
    if (path.distance == 0) return false;
    path.toLight = d / path.distance;
    return true;
}

RGB lightArriving(const World& world, const scene::Light& light, const Vec3& p,
                  const LightPath& path, double selfHit, const LightingQuality& quality,
                  uint64_t& shadowRays, std::span<const scene::Interior* const> startInside) {
    // Shadow rays ignore crossings nearer than povray's shadow tolerance to
    // p or to the light, and that far past each translucent surface
    // (scene/hit_tolerance.h).
    selfHit = std::max(
        selfHit, scene::scaledTolerance(scene::kShadowTolerance, scene::coordinateMagnitude(p, p)));
    // Parallel and cylinder lights fade with the distance from the plane
    // through the light across its axis, on either side of it (measured).
    const bool planar = light.parallel || light.kind == scene::LightKind::Cylinder;
    const double fadeDistance =
        planar ? std::fabs(dot(light.position - p, light.axis())) : path.distance;
    const double att = light.attenuation(p, fadeDistance);
    if (att <= 0) return RGB(0.0);
    // How far from p objects can shadow it.
    double shadowDistance = path.distance;
    if (light.projectedThrough) {
        // Only light that crosses the object on its way to p, and as if it
        // came from there: only what lies between p and the object casts
        // shadows (measured: a bar between the light and the object casts
        // none, a box between the object and the wall does, and a copy of
        // the object placed in the scene does not darken its own
        // projection; lights/projected_through.pov).
        scene::SurfaceHit h;
        if (!light.projectedThrough->firstHit({p, path.toLight}, selfHit, path.distance,
                                              scene::RayKind::Any, h))
            return RGB(0.0);
        shadowDistance = h.t;
    }
    const RGB color = light.color * att;
    if (light.shadowless || !quality.shadows) return color;

    const bool sampleArea =
        light.isArea && quality.areaLights && (light.area.size1 > 1 || light.area.size2 > 1);
    if (!sampleArea) {
        ++shadowRays;
        return color * world.shadowFilter({p, path.toLight}, selfHit, shadowDistance - selfHit,
                                          selfHit, &light, startInside);
    }

    const scene::AreaLight& area = light.area;
    Vec3 axis1 = area.axis1, axis2 = area.axis2;
    if (area.orient) {
        // Turn the grid to face p, keeping the axes' lengths: axis 1 across
        // the light ray and a fixed world axis (z, or x when the ray runs
        // nearly along z), axis 2 across both. The handedness was measured:
        // a pinhole under the light shows povray's sample spots exactly.
        const Vec3& ray = path.toLight;
        const Vec3 helper =
            std::fabs(std::fabs(ray.z) - 1.0) < 0.01 ? Vec3(1, 0, 0) : Vec3(0, 0, 1);
        const Vec3 a1 = normalize(cross(ray, helper));
        const Vec3 a2 = normalize(cross(ray, a1));
        axis1 = a1 * length(area.axis1);
        axis2 = a2 * length(area.axis2);
    }
    const uint64_t seed =
        fmix64(std::bit_cast<uint64_t>(p.x) ^
               fmix64(std::bit_cast<uint64_t>(p.y) ^ fmix64(std::bit_cast<uint64_t>(p.z))));
    // A parallel or cylinder light's grid sits, for p, back along the axis
    // at the distance from the light's location to point_at (measured with
    // a pinhole under a tilted parallel area light: the sample spots match
    // exactly; the light's own plane would tilt them).
    const Vec3 centre =
        planar ? p + path.toLight * length(light.pointAt - light.position) : light.position;
    const GridSampler sampler{world, light, p,    selfHit,    centre,
                              axis1, axis2, seed, shadowRays, startInside};
    // The grid samples carry the light's colour; attenuation (computed at
    // the centre) scales the mean.
    return subdivideAreaGrid(area.size1, area.size2, area.adaptive, sampler) * att;
}

}  // namespace frameray::render
