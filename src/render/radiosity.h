// POV-Ray 3.7's radiosity for one frame: an irradiance cache (Ward's
// method) filled by pretrace passes, then read by the final pass.
//
// Where a diffuse surface is shaded, the light arriving from the other
// surfaces and the sky is interpolated from cached samples that lie near
// enough (within error_bound of their reuse radius, facing alike); where
// too few do (fewer than nearest_count while pretracing, none in the final
// pass unless always_sample), a new sample is gathered: `count` rays in
// cosine-weighted directions over the hemisphere, each shaded as povray
// shades radiosity rays (diffuse light and emission, reflections, no
// highlights, and the radiosity of the surface they hit one bounce deeper,
// up to recursion_limit). The measured rules are in radiosity.cpp.
//
// Determinism: the pretrace passes run in a fixed order on one thread, each
// new sample going straight into the frame's cache; in the final pass every
// block of pixels reads the cache as the pretrace left it plus the samples
// the block itself added. So the image depends on the block size, never on
// the thread count or on which thread renders which block.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "render/radiosity_cache.h"
#include "scene/radiosity.h"
#include "util/color.h"
#include "util/vec3.h"

namespace frameray::render {

// Counters of one frame's radiosity (summed over blocks).
struct RadiosityCounts {
    std::uint64_t samples = 0;  // samples gathered
    std::uint64_t deeper = 0;   // of which for radiosity rays (depth 1 and more)
    std::uint64_t reused = 0;   // lookups answered from the cache

    RadiosityCounts& operator+=(const RadiosityCounts& o) {
        samples += o.samples;
        deeper += o.deeper;
        reused += o.reused;
        return *this;
    }
};

// The frame's radiosity: its settings, the directions samples shoot and
// the cache shared by every block.
class Radiosity {
  public:
    // `eye`: the camera location (reuse radii scale with the distance from
    // it); `legacyAmbient`: a scene before 3.7, whose `ambient` still glows
    // under radiosity (measured: 3.7 scenes ignore it).
    Radiosity(const scene::RadiositySettings& settings, const Vec3& eye, bool legacyAmbient);

    const scene::RadiositySettings& settings() const { return settings_; }
    const Vec3& eye() const { return eye_; }
    bool legacyAmbient() const { return legacyAmbient_; }

    // `count` unit directions in a frame whose z is the surface normal,
    // cosine-weighted and evenly spread (a spiral lattice over the disc,
    // lifted to the hemisphere). Made once for the counts the depths use;
    // any other count (an object's importance) is made into `scratch`.
    std::span<const Vec3> directions(int count, std::vector<Vec3>& scratch) const;

    const std::vector<RadiositySample>& samples() const { return samples_; }
    const RadiosityOctree& octree() const { return octree_; }
    // How far a sample's influence reaches, in units of its radius.
    double reachFactor() const { return reachFactor_; }
    void add(const RadiositySample& sample);

  private:
    scene::RadiositySettings settings_;
    Vec3 eye_;
    bool legacyAmbient_;
    double reachFactor_;
    std::vector<std::vector<Vec3>> directions_;  // count >> depth rays, by depth
    std::vector<RadiositySample> samples_;
    RadiosityOctree octree_;
};

// One block's (or the pretrace's) access to the frame's radiosity: it
// reads the shared cache and keeps the samples it adds, either in the
// shared cache itself (the serial pretrace) or to itself (a block of the
// final pass, so blocks never see each other's samples).
class RadiosityTask {
  public:
    RadiosityTask(Radiosity& radiosity, bool pretrace, bool writeShared)
        : radiosity_(radiosity), pretrace_(pretrace), writeShared_(writeShared) {}

    const Radiosity& radiosity() const { return radiosity_; }
    bool pretrace() const { return pretrace_; }

    // The interpolated irradiance at p (normal n) for a lookup `depth`
    // bounces deep, and how many samples it blends.
    struct Lookup {
        RGB irradiance;
        int found = 0;
    };
    Lookup interpolate(const Vec3& p, const Vec3& n, int depth) const;
    // Whether a lookup that found `found` samples calls for a new one.
    bool wantsSample(int found, int depth) const;
    void add(const RadiositySample& sample);
    // The samples a final-pass block added (moved out).
    std::vector<RadiositySample> takeOwn() { return std::move(own_); }

    RadiosityCounts counts;

  private:
    Radiosity& radiosity_;
    bool pretrace_;
    bool writeShared_;
    std::vector<RadiositySample> own_;  // samples of a final-pass block
};

}  // namespace frameray::render
