// How a ray sees participating media (scene/media.h), as POV-Ray 3.7's
// sampling methods compute it. Method 3 (every figure below measured with
// povray 3.7.0.10 on slabs of media, pixel by pixel):
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
// Methods 1 and 2 (measured against povray 3.7, bit for bit for method 2
// with jitter 0): each interval of length L takes `samples` min samples,
// at (j + 0.5 + jitter * u) / min of it (method 2) or at random (method 1);
// a sample at distance d from the interval's start stands for the whole
// interval: its light times L times exp(-extinction * d), its optical depth
// extinction times L. While the variance of the mean light exceeds
// scene::Media::sampleThreshold (the confidence test) the interval takes
// more random samples, up to `samples` max + 1. The intervals' mean lights
// are added front to back, each dimmed by the mean optical depths of the
// intervals before it. A shadow ray through constant media takes one.
//
// Constant media are sampled over one interval unless a light that
// interacts with media lights the ray (any point light does, a spot or
// cylinder light where the ray crosses its volume): then over `intervals`.
//
// Several media along the same stretch are sampled together with the
// settings of the first one with the most intervals and the smallest
// aa_threshold; their scattering is summed and scattered with the mean
// of their phase functions (a media that does not scatter counts as
// isotropic there), as povray 3.7 does. Jitter and method 1's points are
// hashed from the ray (povray's are random).
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
// `inside`: the interiors the ray is in along the stretch; the samples'
// shadow rays start in them (World::shadowFilter).
MediaResult integrateMedia(const World& world, const LightingQuality& quality,
                           const scene::Ray& ray, double depth, const MediaSet& set, bool lights,
                           uint64_t& samples, uint64_t& shadowRays,
                           std::span<const scene::Interior* const> inside = {});

// The transmittance of the stretch [0, depth] (shadow rays).
RGB mediaTransmittance(const scene::Ray& ray, double depth, const MediaSet& set);

}  // namespace frameray::render
