// Per-pixel comparison of a rendered image against a golden image, the pass
// criterion of the conformance tests. Kept free of any image-file library so
// it can be unit-tested on in-memory pixels.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace frameray::conformance {

// An interleaved image whose samples are 8-bit code values on a 0..255
// scale. Floats so that inputs with more than 8 bits keep their precision.
struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;            // 3 (RGB) or 4 (RGBA)
    std::vector<float> samples;  // width * height * channels, row-major

    float at(int x, int y, int c) const {
        return samples[(static_cast<std::size_t>(y) * width + x) * channels + c];
    }
};

struct CompareOptions {
    // A channel matches when |test - golden| <= tolerance (0..255 scale).
    double tolerance = 4.0;
    // The comparison passes when match >= min_match.
    double min_match = 0.99;
};

struct CompareResult {
    std::size_t total_pixels = 0;
    std::size_t matching_pixels = 0;
    double match = 0.0;         // matching_pixels / total_pixels (1 for empty images)
    double psnr_db = 0.0;       // over R, G, B; +infinity when identical
    double max_abs_diff = 0.0;  // largest channel difference, 0..255 scale
    bool passed = false;
};

// Explains why two images cannot be compared at all (size or channel
// layout), or nothing when they can.
std::optional<std::string> incompatibility(const Image& test, const Image& golden);

// Compares test against golden. R, G and B always take part; alpha takes
// part only when both images have it. The images must be compatible
// (see incompatibility()); otherwise throws std::invalid_argument.
CompareResult compare_images(const Image& test, const Image& golden,
                             const CompareOptions& options = {});

// An RGB image for humans looking at a failure: pixels that fail are red,
// brighter the larger their difference; pixels that match show the golden
// as a dim grey so the failures can be located in the scene.
Image make_diff_image(const Image& test, const Image& golden, const CompareOptions& options = {});

// The image averaged over (2 radius + 1)^2 windows (cut at the borders).
// For scenes with per-pixel randomness that no two renders share (crand):
// both images are smoothed before the per-pixel comparison, so what is
// compared is the local mean.
Image box_blur(const Image& image, int radius);

// One-line report: match, PSNR, max difference and PASS/FAIL.
std::string format_result(const CompareResult& result, const CompareOptions& options);

}  // namespace frameray::conformance
