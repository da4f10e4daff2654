#include "render/antialias.h"

#include <array>
#include <cmath>

#include "render/jitter.h"

namespace frameray::render {

namespace {

// POV-Ray's loop tolerance when stepping through sub-pixel positions.

// Samples of one block plus a one-pixel margin on every side, indexed by
// image pixel coordinates. Method 1 keeps the row above and the column
// left of the block in the margin; method 2 keeps the pixel corners on the
// block's right and bottom edges there.
class BlockGrid {
  public:
    explicit BlockGrid(const PixelBlock& b)
        : x0_(b.x0 - 1),
          y0_(b.y0 - 1),
          width_(b.x1 - b.x0 + 2),
          samples_(size_t(width_) * (b.y1 - b.y0 + 2)),
          done_(samples_.size(), false) {}

    PixelSample& at(int x, int y) { return samples_[index(x, y)]; }
    // Method 1's comparison values of the sample at (x, y)
    // (encodeForComparison of r, g, b), kept with it: each is compared
    // four times.
    std::array<double, 3>& encoded(int x, int y) {
        if (encoded_.empty()) encoded_.resize(samples_.size());
        return encoded_[index(x, y)];
    }
    bool supersampled(int x, int y) const { return done_[index(x, y)]; }
    void markSupersampled(int x, int y) { done_[index(x, y)] = true; }

  private:
    size_t index(int x, int y) const { return size_t(y - y0_) * width_ + (x - x0_); }
    int x0_, y0_, width_;
    std::vector<PixelSample> samples_;
    std::vector<bool> done_;
    std::vector<std::array<double, 3>> encoded_;
};

double encodeForComparison(double v, const AntialiasSettings& s) {
    const double linear = s.toLinear(std::max(v, 0.0));
    return s.gamma > 0 ? std::pow(linear, 1.0 / s.gamma) : linear;
}

// A sample at (x, y), moved by the position's jitter offset scaled by
// `jitterScale` (0: no jitter).
PixelSample jitteredSample(double x, double y, double jitterScale, const SampleFunction& sample,
                           AntialiasCounts& counts) {
    ++counts.samples;
    if (jitterScale <= 0) return sample(x, y);
    const JitterOffset j = jitterAt(x, y);
    return sample(x + j.x * jitterScale, y + j.y * jitterScale);
}

// ---------------------------------------------------------------------------
// Method 1: every pixel is sampled at its centre; a pixel that differs from
// its left or upper neighbour by the threshold or more gets depth x depth
// more samples on a regular (jittered) sub-grid, and so does the neighbour
// unless it already had them. The centre sample stays in the average.

class NonRecursiveSampler {
  public:
    NonRecursiveSampler(const AntialiasSettings& s, const SampleFunction& sample,
                        AntialiasCounts& counts)
        : s_(s), sample_(sample), counts_(counts), jitterScale_(s.jitter / s.depth) {}

    void run(const PixelBlock& b, BlockGrid& grid) {
        // The row above the block: needed for comparisons, never
        // super-sampled here (it belongs to another block).
        for (int x = b.x0; x < b.x1; ++x) {
            grid.at(x, b.y0 - 1) = centreSample(x, b.y0 - 1);
            encode(grid, x, b.y0 - 1);
            grid.markSupersampled(x, b.y0 - 1);
        }
        for (int y = b.y0; y < b.y1; ++y) {
            grid.at(b.x0 - 1, y) = centreSample(b.x0 - 1, y);
            encode(grid, b.x0 - 1, y);
            grid.markSupersampled(b.x0 - 1, y);
            for (int x = b.x0; x < b.x1; ++x) {
                PixelSample& current = grid.at(x, y);
                PixelSample& left = grid.at(x - 1, y);
                PixelSample& top = grid.at(x, y - 1);
                current = centreSample(x, y);
                encode(grid, x, y);
                const bool leftDiffers = distance(grid, x - 1, y, x, y) >= s_.threshold;
                const bool topDiffers = distance(grid, x, y - 1, x, y) >= s_.threshold;
                // Neighbours first, each compared with this pixel's centre
                // sample before this pixel is refined.
                if (leftDiffers && !grid.supersampled(x - 1, y)) {
                    supersample(x - 1, y, left);
                    encode(grid, x - 1, y);
                    grid.markSupersampled(x - 1, y);
                }
                if (topDiffers && !grid.supersampled(x, y - 1)) {
                    supersample(x, y - 1, top);
                    encode(grid, x, y - 1);
                    grid.markSupersampled(x, y - 1);
                }
                if (leftDiffers || topDiffers) {
                    supersample(x, y, current);
                    encode(grid, x, y);
                    grid.markSupersampled(x, y);
                }
            }
        }
    }

  private:
    // Keeps the comparison values of the sample now at (x, y).
    void encode(BlockGrid& grid, int x, int y) {
        const PixelSample& p = grid.at(x, y);
        grid.encoded(x, y) = {encodeForComparison(p.rgb.r, s_), encodeForComparison(p.rgb.g, s_),
                              encodeForComparison(p.rgb.b, s_)};
    }
    // antialiasDistance() of the samples at (ax, ay) and (bx, by), from
    // their kept comparison values (the same sums, so the same bits).
    double distance(BlockGrid& grid, int ax, int ay, int bx, int by) {
        const auto& ea = grid.encoded(ax, ay);
        const auto& eb = grid.encoded(bx, by);
        return std::fabs(ea[0] - eb[0]) + std::fabs(ea[1] - eb[1]) + std::fabs(ea[2] - eb[2]) +
               std::fabs(grid.at(ax, ay).transmit - grid.at(bx, by).transmit);
    }

    PixelSample centreSample(int x, int y) {
        ++counts_.samples;
        return sample_(x, y);
    }

    // Adds the depth x depth sub-grid to `pixel` (which holds the centre
    // sample) and averages all of them.
    void supersample(int x, int y, PixelSample& pixel) {
        ++counts_.supersampledPixels;
        const double step = 1.0 / s_.depth;
        const double range = 0.5 - step * 0.5;
        // depth x depth positions, accumulated exactly as povray steps
        // them: the jitter offset hashes the position's bits.
        double dy = -range;
        for (int row = 0; row < s_.depth; ++row, dy += step) {
            double dx = -range;
            for (int column = 0; column < s_.depth; ++column, dx += step)
                pixel += jitteredSample(x + dx, y + dy, jitterScale_, sample_, counts_);
        }
        pixel *= 1.0 / (s_.depth * s_.depth + 1);
    }

    const AntialiasSettings& s_;
    const SampleFunction& sample_;
    AntialiasCounts& counts_;
    double jitterScale_;
};

// ---------------------------------------------------------------------------
// Method 2: pixels are sampled at their corners; a square whose corners
// differ by the threshold or more is split into four, recursively, down to
// 2^depth subdivisions per pixel side, reusing every sample it already has.

class RecursiveSampler {
  public:
    RecursiveSampler(const AntialiasSettings& s, const SampleFunction& sample,
                     AntialiasCounts& counts)
        : s_(s),
          sample_(sample),
          counts_(counts),
          size_((1 << s.depth) + 1),
          jitterScale_(s.jitter / double(size_)),
          colors_(size_t(size_) * size_),
          sampled_(colors_.size()) {}

    void run(const PixelBlock& b, BlockGrid& grid) {
        // Upper-left corners of every pixel, and of the pixels just right
        // of and below the block (the block's far corners).
        for (int y = b.y0; y <= b.y1; ++y)
            for (int x = b.x0; x <= b.x1; ++x) {
                ++counts_.samples;
                grid.at(x, y) = sample_(x - 0.5, y - 0.5);
            }
        const int last = size_ - 1;
        for (int y = b.y0; y < b.y1; ++y)
            for (int x = b.x0; x < b.x1; ++x) {
                std::fill(sampled_.begin(), sampled_.end(), false);
                store(0, 0, grid.at(x, y));
                store(0, last, grid.at(x, y + 1));
                store(last, 0, grid.at(x + 1, y));
                store(last, last, grid.at(x + 1, y + 1));
                // The pixel's own corner is no longer needed by any later
                // pixel of the row-major walk, so the result replaces it.
                grid.at(x, y) = subdivide(x, y, 0.5, 0, 0, last, s_.depth - 1);
            }
    }

  private:
    PixelSample& cell(int i, int j) { return colors_[size_t(j) * size_ + i]; }
    void store(int i, int j, const PixelSample& c) {
        cell(i, j) = c;
        sampled_[size_t(j) * size_ + i] = true;
    }
    void sampleIfMissing(int i, int j, double x, double y) {
        if (sampled_[size_t(j) * size_ + i]) return;
        store(i, j, jitteredSample(x, y, jitterScale_, sample_, counts_));
    }

    // The square centred on (x, y) with half-size d, whose corners are the
    // sub-grid cells (i, j) and (i + span, j + span).
    PixelSample subdivide(double x, double y, double d, int i, int j, int span, int level) {
        const PixelSample c00 = cell(i, j), c01 = cell(i, j + span), c10 = cell(i + span, j),
                          c11 = cell(i + span, j + span);
        const auto differ = [&](const PixelSample& a, const PixelSample& b) {
            return antialiasDistance(a, b, s_) >= s_.threshold;
        };
        if (level <= 0 || !(differ(c00, c01) || differ(c00, c10) || differ(c00, c11) ||
                            differ(c01, c10) || differ(c01, c11) || differ(c10, c11))) {
            PixelSample sum = c00;
            sum += c01;
            sum += c10;
            sum += c11;
            sum *= 0.25;
            return sum;
        }
        if (level == s_.depth - 1) ++counts_.supersampledPixels;
        const int half = span / 2;
        // Edge midpoints (left, top, right, bottom), then the centre.
        sampleIfMissing(i, j + half, x - d, y);
        sampleIfMissing(i + half, j, x, y - d);
        sampleIfMissing(i + span, j + half, x + d, y);
        sampleIfMissing(i + half, j + span, x, y + d);
        sampleIfMissing(i + half, j + half, x, y);
        const double q = d * 0.5;
        PixelSample sum = subdivide(x - q, y - q, q, i, j, half, level - 1);
        sum += subdivide(x - q, y + q, q, i, j + half, half, level - 1);
        sum += subdivide(x + q, y - q, q, i + half, j, half, level - 1);
        sum += subdivide(x + q, y + q, q, i + half, j + half, half, level - 1);
        sum *= 0.25;
        return sum;
    }

    const AntialiasSettings& s_;
    const SampleFunction& sample_;
    AntialiasCounts& counts_;
    int size_;
    double jitterScale_;
    std::vector<PixelSample> colors_;
    std::vector<bool> sampled_;
};

}  // namespace

double antialiasDistance(const PixelSample& a, const PixelSample& b, const AntialiasSettings& s) {
    return std::fabs(encodeForComparison(a.rgb.r, s) - encodeForComparison(b.rgb.r, s)) +
           std::fabs(encodeForComparison(a.rgb.g, s) - encodeForComparison(b.rgb.g, s)) +
           std::fabs(encodeForComparison(a.rgb.b, s) - encodeForComparison(b.rgb.b, s)) +
           std::fabs(a.transmit - b.transmit);
}

std::vector<PixelSample> sampleBlock(const PixelBlock& b, const AntialiasSettings& s,
                                     const SampleFunction& sample, AntialiasCounts& counts) {
    BlockGrid grid(b);
    if (s.method == 1) {
        NonRecursiveSampler(s, sample, counts).run(b, grid);
    } else if (s.method == 2) {
        RecursiveSampler(s, sample, counts).run(b, grid);
    } else {
        for (int y = b.y0; y < b.y1; ++y)
            for (int x = b.x0; x < b.x1; ++x) {
                ++counts.samples;
                grid.at(x, y) = sample(x, y);
            }
    }
    std::vector<PixelSample> pixels;
    pixels.reserve(size_t(b.x1 - b.x0) * (b.y1 - b.y0));
    for (int y = b.y0; y < b.y1; ++y)
        for (int x = b.x0; x < b.x1; ++x) pixels.push_back(grid.at(x, y));
    return pixels;
}

}  // namespace frameray::render
