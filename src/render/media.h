// How a ray sees participating media (scene/media.h), as POV-Ray 3.7's
// sampling method 3 computes it (every figure below measured with povray
// 3.7.0.10 on slabs of media, pixel by pixel):
//
// - The stretch of ray inside the media is cut into `intervals` equal
//   intervals (one for media without a density, whatever `intervals` says).
// - `samples s` gives each interval N = max(s, 3) / 2 + 1 sub-intervals. The
//   three points of sub-interval k are at (2k, 2k+1, 2k+2) * L / (2N + 2)
//   from the interval's start (L its length): povray spreads N + 1
//   sub-intervals' points but uses only the first N, so the last stretch of
//   every interval is never sampled. Each sub-interval stands for L / N.
// - A sub-interval's value is the mean of its three points unless, below
//   aa_level, the light (emission plus in-scattered light, summed over R,
//   G, B) of an end and the middle one, times the interval's length,
//   differ by aa_threshold or more: then it is the mean of its two halves,
//   a half that differs sampled the same way, one that does not valued as
//   (2 * outer end + middle) / 3. Extinction never splits a sub-interval.
// - Sub-intervals are added front to back: each adds its light times its
//   length, dimmed by the extinction of the sub-intervals before it only.
//
// Several media along the same stretch are sampled together with the first
// one's settings; their scattering is summed and scattered with the mean
// of their phase functions (a media that does not scatter counts as
// isotropic there), as povray 3.7 does. Jitter is hashed from the ray (povray's is random).
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "render/lighting.h"
#include "render/world.h"
#include "scene/media.h"
#include "scene/ray.h"
#include "util/color.h"

namespace frameray::render {

// The media along one stretch of a ray, at most kCapacity of them.
class MediaSet {
  public:
    static constexpr int kCapacity = 16;
    void add(const scene::MediaList& list);
    bool empty() const { return size_ == 0; }
    std::span<const scene::Media* const> media() const { return {items_.data(), size_t(size_)}; }

  private:
    std::array<const scene::Media*, kCapacity> items_{};
    int size_ = 0;
};

struct MediaResult {
    RGB light{0.0};          // added along the stretch
    RGB transmittance{1.0};  // of what lies behind it
};

// `lights`: whether light sources scatter in the media (camera and
// secondary rays) or not (shadow rays, which only need the extinction).
// `ray` has a unit direction; the stretch is [0, depth] along it.
// Counts each sample point in `samples` and shadow rays in `shadowRays`.
MediaResult integrateMedia(const World& world, const LightingQuality& quality,
                           const scene::Ray& ray, double depth, const MediaSet& set, bool lights,
                           uint64_t& samples, uint64_t& shadowRays);

// The transmittance of the stretch [0, depth] (shadow rays).
RGB mediaTransmittance(const scene::Ray& ray, double depth, const MediaSet& set);

}  // namespace frameray::render
