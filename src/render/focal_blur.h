// Focal blur (POV-Ray 3.7 camera `aperture`, `blur_samples`, `focal_point`,
// `confidence`, `variance`): each sample is the average of several rays
// whose origins are spread over the aperture and which all meet again at
// the focal distance, so only that distance is sharp.
//
// The rays follow POV-Ray 3.7's own deterministic scheme, so blurred pixels
// match povray's (facts read from povray's backend/render/tracepixel.cpp,
// backend/support/randomsequences.cpp and jitter.h; the code is ours):
// - Aperture positions: a fixed 4-point square, or a hexagonal grid of 7,
//   19 or 37 points taken in a fixed order, then (beyond the grid) points of
//   the 2-3 Halton sequence on the disc, skipping cells of a coarse
//   coverage grid that already hold a point.
// - Every ray lands on one of 16 x 16 cells of the pixel, the cell chosen
//   through the lattice permutation from a seed of the pixel position and
//   the ray's number, shifted by the anti-aliasing jitter of the cell; the
//   aperture position is jittered by the jitter of the ray's image point.
// - Rays come in batches (the grid's rings, then 4 at a time) until the
//   variance of the mean is below a chi-square threshold.
// Everything is a function of the sample position: images do not depend
// on threads, blocks or the rendered window, as in povray.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "render/antialias.h"
#include "render/camera_rays.h"

namespace frameray::render {

class FocalBlurSampler {
  public:
    explicit FocalBlurSampler(const CameraRays& camera);

    // Traces one sample at image-plane position (x, y) in the anti-aliasing
    // convention (pixel (i, j) is centred at (i, j)); trace() returns the
    // colour along a ray.
    PixelSample sample(double x, double y,
                       const std::function<RGB(const scene::Ray&)>& trace) const;
    // The same with trace() giving colour and transmittance (alpha
    // output); both are averaged and both enter the stopping test.
    PixelSample sample(double x, double y,
                       const std::function<PixelSample(const scene::Ray&)>& trace) const;

    // Aperture positions in the disc of radius 0.5, in the order they are
    // used.
    const std::vector<std::pair<double, double>>& grid() const { return grid_; }
    // Variance below which sampling stops after n samples (index n-1).
    const std::vector<double>& thresholds() const { return thresholds_; }
    // Rays traced before each stopping test, in order (then 4 at a time).
    const std::vector<int>& batches() const { return batches_; }
    // The largest shift of an aperture position (disc units, each axis).
    double gridJitter() const { return gridJitter_; }

    // The image position (anti-aliasing convention) of ray `n` of the
    // sample at (x, y).
    static std::pair<double, double> rayPosition(double x, double y, int n);

  private:
    const CameraRays& camera_;
    std::vector<std::pair<double, double>> grid_;
    std::vector<int> batches_;
    double gridJitter_ = 0;
    std::vector<double> thresholds_;
    Vec3 xPerp_, yPerp_, location_;
    double radius_ = 0, focalScale_ = 1, focalDistance_ = 1;
    bool planar_ = true;  // focus on a plane (perspective, orthographic)
    int minSamples_ = 0, maxSamples_ = 0;
};

}  // namespace frameray::render
