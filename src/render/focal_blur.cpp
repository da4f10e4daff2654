#include "render/focal_blur.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "render/jitter.h"
#include "util/chi_square.h"
#include "util/lattice_hash.h"

namespace frameray::render {

namespace {

// A point of a standard aperture grid: x in half lattice steps, y in rows.
struct GridStep {
    int x, y;
};

// POV-Ray's hexagonal grids (a triangular lattice inside the disc of
// radius 0.5), listed in the order povray traces them: the first batch is
// the centre and six far points, the next batches fill in between.
constexpr std::array<GridStep, 7> kHex7 = {
    {{-2, 0}, {0, 0}, {2, 0}, {-1, 1}, {-1, -1}, {1, 1}, {1, -1}}};
constexpr std::array<GridStep, 19> kHex19 = {{{-2, 2},
                                              {-2, -2},
                                              {2, 2},
                                              {2, -2},
                                              {4, 0},
                                              {-4, 0},
                                              {0, 0},
                                              {0, 2},
                                              {0, -2},
                                              {-3, 1},
                                              {-3, -1},
                                              {3, 1},
                                              {3, -1},
                                              {-1, 1},
                                              {-1, -1},
                                              {1, 1},
                                              {1, -1},
                                              {-2, 0},
                                              {2, 0}}};
constexpr std::array<GridStep, 37> kHex37 = {
    {{0, 0},   {-3, 3},  {3, -3}, {-3, -3}, {3, 3},   {-6, 0}, {6, 0},  {-2, 2},
     {2, -2},  {-2, -2}, {2, 2},  {-4, 0},  {4, 0},   {-1, 1}, {1, -1}, {-1, -1},
     {1, 1},   {-2, 0},  {2, 0},  {-5, 1},  {-5, -1}, {5, 1},  {5, -1}, {-4, 2},
     {-4, -2}, {4, 2},   {4, -2}, {-1, 3},  {-1, -3}, {1, 3},  {1, -3}, {-3, 1},
     {-3, -1}, {3, 1},   {3, -1}, {0, 2},   {0, -2}}};

// Radical inverse of k in `base` (the Halton sequence's k-th value).
double radicalInverse(unsigned k, unsigned base) {
    double value = 0, digitWeight = 1.0 / base;
    for (; k > 0; k /= base, digitWeight /= base) value += (k % base) * digitWeight;
    return value;
}

// Point `index` (from 0) of the 2-3 Halton sequence mapped uniformly onto
// the disc of radius 0.5 (squared radius from base 2, angle from base 3).
std::pair<double, double> haltonOnDisc(unsigned index) {
    const double r = std::sqrt(radicalInverse(index + 1, 2) * 0.25);
    const double theta = radicalInverse(index + 1, 3) * (2 * std::numbers::pi);
    return {r * std::cos(theta), r * std::sin(theta)};
}

// povray's aperture positions for `count` rays (disc of radius 0.5), the
// ray batches of its grid and the per-axis jitter of a position.
void apertureGrid(int count, std::vector<std::pair<double, double>>& grid,
                  std::vector<int>& batches, double& jitter) {
    grid.clear();
    batches.clear();
    int rings = 0;
    if (count >= 37)
        rings = 3;
    else if (count >= 19)
        rings = 2;
    else if (count >= 7)
        rings = 1;
    // Below 7 rays: a 2 x 2 square.
    if (rings == 0) {
        for (const auto& [sx, sy] :
             std::array<std::pair<int, int>, 4>{{{-1, 1}, {1, 1}, {-1, -1}, {1, -1}}})
            grid.emplace_back(0.25 * sx, 0.25 * sy);
    } else {
        // Half a lattice step and a row of the triangular lattice whose
        // `rings` rings fill the disc.
        const double halfStep = 1.0 / (2 * (rings + 1) * std::sqrt(3.0));
        const double row = 1.0 / (2 * (rings + 1));
        const GridStep* steps = rings == 1   ? kHex7.data()
                                : rings == 2 ? kHex19.data()
                                             : kHex37.data();
        const int size = rings == 1 ? 7 : rings == 2 ? 19 : 37;
        for (int i = 0; i < size; ++i) grid.emplace_back(steps[i].x * halfStep, steps[i].y * row);
        if (rings == 1) batches = {7};
        if (rings == 2) batches = {7, 6, 6};
        if (rings == 3) batches = {7, 6, 6, 4, 4, 4, 4, 2};
        if (count == size) jitter = halfStep;
    }
    if (count != 7 && count != 19 && count != 37) jitter = 0.5 / std::sqrt(double(count));
    const int standard = static_cast<int>(grid.size());
    if (count <= standard) {
        grid.resize(static_cast<size_t>(count));
        return;
    }
    // The rest from the Halton sequence on the disc, each in a cell of an
    // odd-sized coverage grid that holds no point yet while candidates
    // last (10 per ray in all).
    const int cells = 2 * static_cast<int>(std::ceil(std::sqrt(count / std::numbers::pi))) + 1;
    std::vector<int> used(static_cast<size_t>(cells) * cells, 0);
    const auto cellOf = [&](double x, double y, bool clamp) {
        int cx = static_cast<int>((x + 0.5) * cells), cy = static_cast<int>((y + 0.5) * cells);
        if (clamp) cx = std::min(cx, cells - 1), cy = std::min(cy, cells - 1);
        return static_cast<size_t>(cy) * cells + cx;
    };
    for (const auto& [x, y] : grid) ++used[cellOf(x, y, false)];
    long candidates = 10L * count;
    unsigned next = 0;
    for (int i = standard; i < count; ++i) {
        auto point = haltonOnDisc(next++);
        --candidates;
        while ((used[cellOf(point.first, point.second, true)] != 0 ||
                point.first * point.first + point.second * point.second > 0.25) &&
               candidates > count - i) {
            point = haltonOnDisc(next++);
            --candidates;
        }
        grid.push_back(point);
        ++used[cellOf(point.first, point.second, true)];
    }
}

}  // namespace

FocalBlurSampler::FocalBlurSampler(const CameraRays& camera) : camera_(camera) {
    const scene::Camera& c = camera.camera();
    maxSamples_ = std::max(c.blur.blurSamples, 1);
    minSamples_ = std::clamp(c.blur.minSamples, 0, maxSamples_);
    apertureGrid(maxSamples_, grid_, batches_, gridJitter_);
    // The grid's disc (radius 0.5) spans the aperture's radius.
    radius_ = 0.5 * c.blur.aperture;
    // Rays meet again at the focal point's distance from the eye, measured
    // along the view: a perspective ray's unnormalised direction scaled by
    // F / |direction| reaches the plane at distance F square to the view
    // (povray keeps off-axis objects on that plane sharp).
    focalDistance_ =
        c.blur.focalPointGiven ? length(c.blur.focalPoint - c.location) : length(c.direction);
    if (focalDistance_ == 0) focalDistance_ = 1;
    focalScale_ = focalDistance_ / length(c.direction);
    location_ = c.location;
    planar_ = c.projection == scene::Projection::Perspective ||
              c.projection == scene::Projection::Orthographic;
    // A "+" on the lens: right-ish and up-ish, perpendicular to the view.
    xPerp_ = normalize(cross(c.up, c.direction));
    yPerp_ = normalize(cross(c.direction, xPerp_));

    // Stop once the variance of the mean is below these (scaled chi-square
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

std::pair<double, double> FocalBlurSampler::rayPosition(double x, double y, int n) {
    // One of 16 x 16 cells of the pixel, picked by the lattice permutation
    // from a seed of the position, then moved by up to one cell (left/up)
    // by the anti-aliasing jitter of the cell's offset.
    constexpr int kCells = 16;
    const int seed = static_cast<int>(x * 313.0 + 11.0) + static_cast<int>(y * 311.0 + 17.0);
    const int cellX = kLatticeHash[static_cast<unsigned>(seed + n) & 0xfff] % kCells;
    const int cellY = kLatticeHash[static_cast<unsigned>(seed + n + 1) & 0xfff] % kCells;
    double dx = double(2 * cellX + 1) / double(2 * kCells) - 0.5;
    double dy = double(2 * cellY + 1) / double(2 * kCells) - 0.5;
    const JitterOffset shift = jitterAt(dx, dy);
    dx += (shift.x - 0.5) / kCells;
    dy += (shift.y - 0.5) / kCells;
    return {x + dx, y + dy};
}

PixelSample FocalBlurSampler::sample(double x, double y,
                                     const std::function<RGB(const scene::Ray&)>& trace) const {
    return sample(x, y, std::function<PixelSample(const scene::Ray&)>([&](const scene::Ray& r) {
                      return PixelSample{trace(r), 0.0};
                  }));
}

PixelSample FocalBlurSampler::sample(
    double x, double y, const std::function<PixelSample(const scene::Ray&)>& trace) const {
    PixelSample sum;    // colours of the traced rays
    PixelSample total;  // every ray's colour (a ray the projection lacks: clear black)
    PixelSample squares;
    int n = 0;
    size_t batch = 0;
    do {
        const int rays = batch < batches_.size() ? batches_[batch++] : 4;
        for (int i = 0; i < rays && n < maxSamples_; ++i, ++n) {
            const auto [sx, sy] = rayPosition(x, y, n);
            const std::optional<scene::Ray> base = camera_.generateUnnormalized(sx + 0.5, sy + 0.5);
            PixelSample colour{RGB{}, 1.0};
            if (base) {
                // The aperture position, jittered by the ray's image point
                // (povray's pixel-corner convention: x + 1/2, y - 1/2).
                const JitterOffset shift = jitterAt(sx + 0.5, sy - 0.5);
                const auto [gx, gy] = grid_[static_cast<size_t>(n)];
                const double lx = radius_ * (gx + shift.x * gridJitter_ * 2.0);
                const double ly = radius_ * (gy + shift.y * gridJitter_ * 2.0);
                const Vec3 offset = xPerp_ * lx - yPerp_ * ly;
                // Move the eye across the aperture and aim back at the point
                // the unblurred ray reaches at the focal distance. The eye
                // is the camera's location for every projection (povray:
                // an orthographic or cylindrical camera's per-pixel origin
                // is dropped when it blurs).
                const Vec3 target = planar_ ? base->direction * focalScale_
                                            : normalize(base->direction) * focalDistance_;
                colour = trace(scene::Ray{location_ + offset, normalize(target - offset)});
                sum.rgb += colour.rgb;
                sum.transmit += colour.transmit;
            }
            total.rgb += colour.rgb;
            total.transmit += colour.transmit;
            squares.rgb += RGB(colour.rgb.r * colour.rgb.r, colour.rgb.g * colour.rgb.g,
                               colour.rgb.b * colour.rgb.b);
            squares.transmit += colour.transmit * colour.transmit;
        }
        if (n < minSamples_) continue;
        // Variance of the mean of n rays, per channel.
        const double inv = 1.0 / n;
        const double limit = thresholds_[static_cast<size_t>(n - 1)];
        const auto small = [&](double s, double q) {
            return (q * inv - (s * inv) * (s * inv)) * inv < limit;
        };
        if (small(total.rgb.r, squares.rgb.r) && small(total.rgb.g, squares.rgb.g) &&
            small(total.rgb.b, squares.rgb.b) && small(total.transmit, squares.transmit))
            break;
    } while (n < maxSamples_);
    sum *= 1.0 / n;
    return sum;
}

}  // namespace frameray::render
