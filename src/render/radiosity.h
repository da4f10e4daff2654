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

#include <algorithm>
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

// What changes with the depth of a lookup or sample (povray 3.7's rules,
// depth d = how many radiosity rays deep): rays per new sample halve per
// bounce (at least 5); the error bound and the reuse radius limits double;
// the weight a lookup must find before it reuses (nearest_count at the top,
// at most 2 one bounce deep, 1 deeper); and how far the cache lets a
// sample be found: a top-level sample wherever its whole reach goes,
// a deeper one only within an eighth of it (povray files deeper samples in
// octree cells sized for an eighth of their reach, so lookups farther away
// never see them).
struct RadiosityDepth {
    int rays = 0;
    double reuseWeight = 0;
    double boundFactor = 1;
    double minimumReuse = 0;
    double maximumReuse = 0;
    double cellFactor = 0;  // a sample's cell is sized for radius * cellFactor
};

// The cell of the cache a sample is filed in (a power-of-two cube, in
// coordinates shifted by a large bias so that every index is positive): a
// lookup sees the sample only from within the cell widened by half its size.
struct RadiosityCell {
    double size = 0;
    double cx = 0, cy = 0, cz = 0;  // the cell's centre, biased coordinates

    bool sees(const Vec3& p) const;
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
    const RadiosityDepth& depth(int d) const {
        return depths_[static_cast<size_t>(std::min<int>(d, static_cast<int>(depths_.size()) - 1))];
    }

    // The pool of directions samples take their rays from, in turn (the
    // second value of `count`, at least `count`; povray's default 1600):
    // each sample takes the next `count` consecutive entries. Measured
    // from povray 3.7 (a sky-only scene whose sky colour encodes the
    // direction, one new sample per pixel, 16-bit output): entry j is
    // point j+1 of the Halton sequence in bases 2 and 3, lifted to the
    // hemisphere cosine-weighted (sin^2 of the angle from the normal = the
    // base-2 radical inverse, the turn around it = the base-3 one), so any
    // run of consecutive entries is stratified on its own. povray uses
    // this for pools of 1600 and more (the default); for smaller pools it
    // uses another table, not measured: frameray takes the same sequence.
    size_t poolSize() const { return poolSize_; }
    // Pool entry `index` in a frame whose z is the surface normal.
    static Vec3 direction(size_t index);
    // The frame povray 3.7 turns pool entries into for unit normal n
    // (measured as above): u = n x z normalized, or n x y where |n.z| is
    // 0.9 or more; v = u x n; w = n. World direction = u*x + v*y + w*z.
    // Within 0.001 of +y or -y (n.y beyond 1 - 0.001) povray takes the
    // entries as they are, (x, z, y), or negated (its source).
    static void sampleFrame(const Vec3& n, Vec3& u, Vec3& v, Vec3& w);
    const std::vector<RadiositySample>& samples() const { return samples_; }
    const std::vector<RadiosityCell>& cells() const { return cells_; }
    const RadiosityOctree& octree() const { return octree_; }
    void add(const RadiositySample& sample);
    RadiosityCell cellOf(const RadiositySample& sample) const;

  private:
    scene::RadiositySettings settings_;
    Vec3 eye_;
    bool legacyAmbient_;
    std::vector<RadiosityDepth> depths_;
    size_t poolSize_;
    std::vector<RadiositySample> samples_;
    std::vector<RadiosityCell> cells_;
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
    // The pretrace pass (1, 2, ...) and tile the task is working on.
    void setTile(int pass, int tile) {
        pass_ = pass;
        tile_ = tile;
    }

    // The interpolated irradiance at p (normal n) for a lookup `depth`
    // bounces deep, how many samples it blends and their summed weight.
    // `weight`: how much the light found here can still matter to the
    // pixel (below 1/4 the error bound widens by the difference).
    struct Lookup {
        RGB irradiance;
        int found = 0;
        double weight = 0;
    };
    Lookup interpolate(const Vec3& p, const Vec3& n, int depth, double weight = 1.0) const;
    // Whether a lookup calls for a new sample.
    bool wantsSample(const Lookup& found, int depth) const;
    void add(RadiositySample sample);
    // The samples a final-pass block added (moved out).
    std::vector<RadiositySample> takeOwn() { return std::move(own_); }
    // Where in the pool the next sample `depth` deep starts, taking
    // `count` directions (each depth takes its own turn through the pool).
    size_t takeDirections(int depth, size_t count);
    // Where each depth's turn through the pool stands, and whether this
    // task took any directions (gathered any sample, kept or not).
    const std::vector<size_t>& cursor() const { return cursor_; }
    void setCursor(std::vector<size_t> cursor) { cursor_ = std::move(cursor); }
    bool gathered() const { return gathered_; }
    // The box around every point this task looked the light up at (any
    // depth); empty() when it looked nothing up.
    struct Box {
        Vec3 lo, hi;
        bool empty = true;
    };
    const Box& lookups() const { return lookups_; }

    RadiosityCounts counts;
    // Top-level lookups since the counters were last reset, and the
    // weights they found (before gathering) times 4: the adaptive
    // pretrace's coverage (nearest_count's second value) is their ratio.
    long topQueries = 0;
    double topCoverage = 0;

  private:
    Radiosity& radiosity_;
    bool pretrace_;
    bool writeShared_;
    int pass_ = 0;
    int tile_ = 0;
    std::vector<RadiositySample> own_;  // samples of a final-pass block
    std::vector<RadiosityCell> ownCells_;
    std::vector<size_t> cursor_;  // per depth: where in the pool the next sample starts
    bool gathered_ = false;
    mutable Box lookups_;
};

}  // namespace frameray::render
