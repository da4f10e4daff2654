#include "render/focal_blur.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "util/chi_square.h"
#include "util/sample_random.h"

namespace frameray::render {

namespace {

// Hexagonal-lattice points within `rings` rings of the centre, centre
// first then ring by ring, scaled into the unit disc.
std::vector<std::pair<double, double>> hexGrid(int rings, double& spacing) {
    spacing = 1.0 / (rings + 0.5);
    std::vector<std::pair<double, double>> points;
    for (int ring = 0; ring <= rings; ++ring)
        for (int q = -ring; q <= ring; ++q)
            for (int r = -ring; r <= ring; ++r) {
                const int s = -q - r;
                if (std::max({std::abs(q), std::abs(r), std::abs(s)}) != ring) continue;
                const double px = spacing * (q + 0.5 * r);
                const double py = spacing * (std::sqrt(3.0) / 2.0 * r);
                points.emplace_back(px, py);
            }
    return points;
}

}  // namespace

FocalBlurSampler::FocalBlurSampler(const CameraRays& camera) : camera_(camera) {
    const scene::Camera& c = camera.camera();
    maxSamples_ = std::max(c.blur.blurSamples, 1);
    minSamples_ = std::clamp(c.blur.minSamples, 1, maxSamples_);
    // The aperture spread that best matches povray's blur (measured over
    // 7 and 37 samples: the grid's disc has a quarter of the aperture as
    // radius, i.e. the aperture is the disc's diameter at half scale).
    radius_ = 0.25 * c.blur.aperture;
    // Rays meet again on the plane through the focal point square to the
    // view direction (measured: povray keeps off-axis objects on that
    // plane sharp, not those at the focal point's distance).
    directionLength_ = length(c.direction);
    focalDistance_ = dot(c.blur.focalPoint - c.location, c.direction / directionLength_);
    planar_ = c.projection == scene::Projection::Perspective ||
              c.projection == scene::Projection::Orthographic;
    // A "+" on the lens: right-ish and up-ish, perpendicular to the view.
    xPerp_ = normalize(cross(c.up, c.direction));
    yPerp_ = normalize(cross(c.direction, xPerp_));

    // povray's grid sizes: 7, 19 or 37 hexagonal points, random beyond.
    if (maxSamples_ <= 37) {
        const int rings = maxSamples_ <= 7 ? 1 : (maxSamples_ <= 19 ? 2 : 3);
        grid_ = hexGrid(rings, gridJitter_);
        grid_.resize(static_cast<size_t>(maxSamples_));
    } else {
        SampleRandom random(-1.0, -1.0, 1);
        while (static_cast<int>(grid_.size()) < maxSamples_) {
            const double px = 2 * random.next() - 1, py = 2 * random.next() - 1;
            if (px * px + py * py <= 1) grid_.emplace_back(px, py);
        }
        gridJitter_ = 0;
    }

    // Stop once the colour variance is below these (scaled chi-square
    // quantiles, so fewer samples need a smaller variance).
    thresholds_.assign(static_cast<size_t>(maxSamples_), 0.0);
    if (maxSamples_ > 1) {
        const double base =
            c.blur.variance / chiSquareUpperTailInverse(maxSamples_ - 1, c.blur.confidence);
        for (int i = 0; i < maxSamples_; ++i)
            thresholds_[static_cast<size_t>(i)] =
                base * chiSquareUpperTailInverse(i + 1, c.blur.confidence);
    }
}

PixelSample FocalBlurSampler::sample(double x, double y,
                                     const std::function<RGB(const scene::Ray&)>& trace) const {
    return sample(x, y, std::function<PixelSample(const scene::Ray&)>([&](const scene::Ray& r) {
                      return PixelSample{trace(r), 0.0};
                  }));
}

PixelSample FocalBlurSampler::sample(
    double x, double y, const std::function<PixelSample(const scene::Ray&)>& trace) const {
    SampleRandom random(x, y);
    PixelSample sum;
    RGB squares;
    int n = 0;
    int batch = std::max(minSamples_, std::min(4, maxSamples_));
    for (;;) {
        for (int i = 0; i < batch && n < maxSamples_; ++i, ++n) {
            // A random position inside the pixel.
            const double sx = x + random.next() - 0.5, sy = y + random.next() - 0.5;
            const std::optional<scene::Ray> base = camera_.generateUnnormalized(sx, sy);
            const double jx = (random.next() - 0.5) * gridJitter_,
                         jy = (random.next() - 0.5) * gridJitter_;
            if (!base) {
                sum.transmit += 1;
                continue;
            }
            const auto [gx, gy] = grid_[static_cast<size_t>(n)];
            const Vec3 offset = xPerp_ * (radius_ * (gx + jx)) - yPerp_ * (radius_ * (gy + jy));
            // Move the eye across the aperture and aim back at the point
            // the unblurred ray reaches at the focal distance.
            // (Perspective rays scaled by F/|direction| reach the focal
            // plane; the angular projections use the distance.)
            const Vec3 target = planar_ ? base->direction * (focalDistance_ / directionLength_)
                                        : normalize(base->direction) * focalDistance_;
            const scene::Ray ray{base->origin + offset, normalize(target - offset)};
            const PixelSample traced = trace(ray);
            const RGB& colour = traced.rgb;
            sum.rgb += colour;
            sum.transmit += traced.transmit;
            squares += RGB(colour.r * colour.r, colour.g * colour.g, colour.b * colour.b);
        }
        if (n >= maxSamples_) break;
        const double inv = 1.0 / n;
        const RGB mean = sum.rgb * inv;
        const double threshold = thresholds_[static_cast<size_t>(n - 1)];
        if (squares.r * inv - mean.r * mean.r < threshold &&
            squares.g * inv - mean.g * mean.g < threshold &&
            squares.b * inv - mean.b * mean.b < threshold)
            break;
        batch = 4;
    }
    sum *= 1.0 / n;
    return sum;
}

}  // namespace frameray::render
