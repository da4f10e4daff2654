// The tracer's side of radiosity (render/radiosity.h): looking the light
// up in the cache, and gathering a new sample with radiosity rays.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/tracer.h"
#include "util/sample_random.h"

namespace frameray::render {

namespace {

// A frame around unit normal n (z = n) that turns smoothly with n except
// near one axis, so neighbouring samples on a curved surface shoot nearly
// the same directions.
void tangentFrame(const Vec3& n, Vec3& u, Vec3& v) {
    const Vec3 helper = std::fabs(n.y) < 0.9 ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
    u = normalize(cross(helper, n));
    v = cross(n, u);
}

}  // namespace

RGB Tracer::radiosityLight(const Vec3& p, const Vec3& n, const scene::Object& obj, double eps,
                           const State& state, RayCounts& counts) const {
    RadiosityTask* task = state.radiosity.task;
    if (!task) return RGB(0.0);
    const scene::RadiositySettings& set = radiosity_->settings();
    const int depth = state.radiosity.depth;
    // Measured with two facing planes: recursion_limit n lets light bounce
    // n times; the last surface reached adds no radiosity (and, povray
    // 3.7, no ambient either).
    if (depth >= set.recursionLimit) return RGB(0.0);
    const RadiosityTask::Lookup found = task->interpolate(p, n, depth);
    if (!task->wantsSample(found.found, depth)) {
        ++task->counts.reused;
        return found.irradiance;
    }
    const RadiositySample sample = gatherSample(p, n, obj, eps, state, counts);
    task->add(sample);
    return sample.irradiance;
}

RadiositySample Tracer::gatherSample(const Vec3& p, const Vec3& n, const scene::Object& obj,
                                     double eps, const State& state, RayCounts& counts) const {
    const scene::RadiositySettings& set = radiosity_->settings();
    // Each bounce deeper shoots half as many rays (povray's ray counts per
    // depth: 200, 100, 50 with count 200).
    int count = std::max(1, set.count >> std::min(state.radiosity.depth, 30));
    if (obj.radiosityImportance > 0)
        count = std::max(1, static_cast<int>(std::ceil(count * obj.radiosityImportance)));
    Vec3 u, v;
    tangentFrame(n, u, v);
    {
        // Each sample turns the pattern by its own angle, hashed from its
        // point, so neighbouring samples' errors differ and blending them
        // averages the errors out.
        SampleRandom turn(p.x + 0.5 * p.z, p.y - 0.25 * p.z, 0x7a11ULL);
        const double a = turn.next() * 2 * std::numbers::pi;
        const Vec3 u2 = u * std::cos(a) + v * std::sin(a);
        v = v * std::cos(a) - u * std::sin(a);
        u = u2;
    }
    const double pathLength = state.radiosity.length + length(p - state.radiosity.origin);

    State child;
    child.level = state.level + 1;
    child.weight = state.weight;
    child.kind = scene::RayKind::Radiosity;
    child.inside = state.inside;
    child.band = state.band;
    child.radiosity = {state.radiosity.task, state.radiosity.depth + 1, true, p, pathLength};
    double distance = 0;
    child.hitDistance = &distance;

    RGB sum(0.0);
    double inverseDistances = 0;
    std::vector<Vec3> scratch;
    for (const Vec3& d : radiosity_->directions(count, scratch)) {
        const Vec3 dir = u * d.x + v * d.y + n * d.z;
        ++counts.radiosity;
        RGB c = trace({p, dir}, eps, child, counts);
        // max_sample: no ray brings more than this (by its brightest channel).
        if (set.maxSample > 0) {
            const double m = c.maxComponent();
            if (m > set.maxSample) c = c * (set.maxSample / m);
        }
        sum += c;
        if (distance < scene::kInfinity) inverseDistances += 1.0 / std::max(distance, 1e-12);
    }
    RGB e = sum * (1.0 / count);
    if (set.grayThreshold > 0) {
        const double grey = (e.r + e.g + e.b) / 3.0;
        e = e * (1.0 - set.grayThreshold) + RGB(grey * set.grayThreshold);
    }
    e = e * set.brightness;

    RadiositySample s;
    s.point = p;
    s.normal = n;
    s.irradiance = e;
    s.depth = state.radiosity.depth;
    // The harmonic mean distance of the surfaces the rays met, within
    // minimum_reuse and maximum_reuse of the distance from the eye
    // (measured from povray's saved samples).
    const double harmonic = inverseDistances > 0 ? count / inverseDistances : scene::kInfinity;
    s.radius = std::clamp(harmonic, set.minimumReuse * pathLength, set.maximumReuse * pathLength);
    return s;
}

}  // namespace frameray::render
