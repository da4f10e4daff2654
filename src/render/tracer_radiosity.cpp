// The tracer's side of radiosity (render/radiosity.h): looking the light
// up in the cache, and gathering a new sample with radiosity rays.
#include <algorithm>
#include <cmath>

#include "render/tracer.h"

namespace frameray::render {

RGB Tracer::radiosityLight(const Vec3& p, const Vec3& n, const scene::Object& obj, double eps,
                           double weight, const State& state, RayCounts& counts) const {
    RadiosityTask* task = state.radiosity.task;
    if (!task) return RGB(0.0);
    const scene::RadiositySettings& set = radiosity_->settings();
    const int depth = state.radiosity.depth;
    // Measured with two facing planes: recursion_limit n lets light bounce
    // n times; the last surface reached adds no radiosity (and, povray
    // 3.7, no ambient either).
    if (depth >= set.recursionLimit) return RGB(0.0);
    const RadiosityTask::Lookup found = task->interpolate(p, n, depth, weight);
    if (depth == 0) {
        ++task->topQueries;
        task->topCoverage += 4 * found.weight;
    }
    // povray 3.7: a radiosity ray's quality is the least, over the lookups
    // it met, of the weight found over the weight a reuse needs (times 4);
    // the gathering sample weighs its rays by it.
    const double needed = radiosity_->depth(depth).reuseWeight;
    const auto rate = [&](double reuse) {
        if (state.radiosity.quality)
            *state.radiosity.quality = std::min(*state.radiosity.quality, 4 * reuse / needed);
    };
    if (!task->wantsSample(found, depth)) {
        ++task->counts.reused;
        rate(found.weight);
        return found.irradiance;
    }
    bool keep = false;
    const RadiositySample sample = gatherSample(p, n, obj, eps, state, counts, keep);
    if (keep) task->add(sample);
    // A new sample's rays leave the quality of the ray that asked for it
    // at least theirs (povray restores it so).
    if (state.radiosity.quality)
        *state.radiosity.quality = std::max(*state.radiosity.quality, sample.quality);
    // povray 3.7: the samples already found nearby are not thrown away; the
    // new one joins them, weighted by its quality.
    rate(found.weight + sample.quality);
    if (found.weight > 0)
        return (found.irradiance * found.weight + sample.irradiance * sample.quality) *
               (1.0 / (found.weight + sample.quality));
    return sample.irradiance;
}

RadiositySample Tracer::gatherSample(const Vec3& p, const Vec3& n, const scene::Object& obj,
                                     double eps, const State& state, RayCounts& counts,
                                     bool& keep) const {
    const scene::RadiositySettings& set = radiosity_->settings();
    const int depth = state.radiosity.depth;
    const RadiosityDepth& at = radiosity_->depth(depth);
    int count = at.rays;
    if (obj.radiosityImportance > 0)
        count = std::max(1, static_cast<int>(std::ceil(count * obj.radiosityImportance)));
    count = std::min(count, static_cast<int>(radiosity_->poolSize()));
    const size_t first = state.radiosity.task->takeDirections(depth, static_cast<size_t>(count));
    Vec3 u, v, w;
    Radiosity::sampleFrame(n, u, v, w);
    const double pathLength = state.radiosity.length + length(p - state.radiosity.origin);

    State child;
    child.level = state.level + 1;
    // povray 3.7 traces radiosity rays as if they carried half the light
    // (a quarter one bounce deeper, ...), for adc_bailout.
    child.weight = std::max(set.adcBailout + 1e-6, std::pow(0.5 * set.brightness, depth + 1));
    child.kind = scene::RayKind::Radiosity;
    child.inside = state.inside;
    child.band = state.band;
    double quality = 1;
    child.radiosity = {state.radiosity.task, depth + 1, true, p, pathLength, &quality};
    double distance = 0;
    child.hitDistance = &distance;

    RGB sum(0.0);
    double inverseDistances = 0;
    double qualitySum = 0;
    // Where no ray meets a surface, povray 3.7 keeps its "nothing found"
    // distance (2e10) and no direction toward the nearest surface (a zero
    // vector), so such a sample's reach is not stretched along any
    // direction.
    constexpr double kNothingNear = 2e10;
    double nearest = kNothingNear;
    Vec3 toNearest(0, 0, 0);
    for (int i = 0; i < count; ++i) {
        const Vec3 d =
            Radiosity::direction((first + static_cast<size_t>(i)) % radiosity_->poolSize());
        const Vec3 dir = u * d.x + v * d.y + w * d.z;
        ++counts.radiosity;
        quality = 1;
        RGB c = trace({p, dir}, eps, child, counts);
        // max_sample: no ray brings more than this (by its brightest channel).
        if (set.maxSample > 0) {
            const double m = c.maxComponent();
            if (m > set.maxSample) c = c * (set.maxSample / m);
        }
        sum += c * quality;
        qualitySum += quality;
        if (distance < scene::kInfinity) {
            inverseDistances += 1.0 / std::max(distance, 1e-12);
            if (distance < nearest) {
                nearest = distance;
                toNearest = dir;
            }
        }
    }
    // Each ray counts by its quality.
    RGB e = qualitySum > 0 ? sum * (1.0 / qualitySum) : sum;
    if (set.grayThreshold > 0) {
        const double grey = (e.r + e.g + e.b) / 3.0;
        e = e * (1.0 - set.grayThreshold) + RGB(grey * set.grayThreshold);
    }
    e = e * set.brightness;

    RadiositySample s;
    s.point = p;
    s.normal = n;
    s.irradiance = e;
    s.depth = depth;
    s.quality = qualitySum / count;
    // The harmonic mean distance of the surfaces the rays met, within
    // minimum_reuse and maximum_reuse (doubled per bounce) of the distance
    // from the eye.
    const double toEye = length(radiosity_->eye() - p);
    const double harmonic = inverseDistances > 0 ? count / inverseDistances : scene::kInfinity;
    const double most = at.maximumReuse * toEye;
    s.radius = std::clamp(harmonic, at.minimumReuse * toEye, most);
    s.nearest = nearest;
    s.toNearest = toNearest;
    // A sample whose rays almost touched a surface is not kept.
    keep = nearest > most * 1e-4;
    return s;
}

}  // namespace frameray::render
