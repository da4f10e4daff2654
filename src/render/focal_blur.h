// Focal blur (POV-Ray 3.7 camera `aperture`, `blur_samples`, `focal_point`,
// `confidence`, `variance`): each sample is the average of several rays
// whose origins are spread over the aperture and which all meet again at
// the focal distance, so only that distance is sharp.
//
// As in povray, every ray also lands at a random position inside the pixel
// (blur replaces the one centre ray), the aperture positions come from a
// hexagonal grid (random points beyond 37 samples) with jitter, and rays
// are taken in batches until the colour's variance is small enough for the
// requested confidence, or blur_samples is reached. povray's random numbers
// come from a per-thread generator and cannot be reproduced; ours are
// seeded from the sample position (deterministic whatever the threads).
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

    // Traces one sample at image-plane position (x, y) (pixel (i, j) spans
    // [i, i+1) x [j, j+1)); trace() returns the colour along a ray.
    PixelSample sample(double x, double y,
                       const std::function<RGB(const scene::Ray&)>& trace) const;
    // The same with trace() giving colour and transmittance (alpha
    // output); both are averaged, the stopping test sees the colour.
    PixelSample sample(double x, double y,
                       const std::function<PixelSample(const scene::Ray&)>& trace) const;

    // Aperture positions in the unit disc, in the order they are used.
    const std::vector<std::pair<double, double>>& grid() const { return grid_; }
    // Variance below which sampling stops after n samples (index n-1).
    const std::vector<double>& thresholds() const { return thresholds_; }

  private:
    const CameraRays& camera_;
    std::vector<std::pair<double, double>> grid_;
    double gridJitter_ = 0;  // jitter of a grid point, in unit-disc units
    std::vector<double> thresholds_;
    Vec3 xPerp_, yPerp_;
    double radius_ = 0, focalDistance_ = 0, directionLength_ = 1;
    bool planar_ = true;  // focus on a plane (perspective, orthographic)
    int minSamples_ = 0, maxSamples_ = 0;
};

}  // namespace frameray::render
