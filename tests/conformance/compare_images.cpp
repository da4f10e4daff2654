#include "compare_images.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace frameray::conformance {
namespace {

// Differences are computed in float from samples that are often exact
// 8-bit integers that went through a /255 and *255 round trip; the slack
// keeps an exact 4/255 difference on the matching side.
constexpr double kToleranceSlack = 1e-3;

int compared_channels(const Image& test, const Image& golden) {
    return (test.channels == 4 && golden.channels == 4) ? 4 : 3;
}

}  // namespace

std::optional<std::string> incompatibility(const Image& test, const Image& golden) {
    for (const Image* image : {&test, &golden}) {
        const char* which = image == &test ? "test" : "golden";
        if (image->channels != 3 && image->channels != 4) {
            return std::string(which) + " image has " + std::to_string(image->channels) +
                   " channels; expected RGB or RGBA";
        }
        const std::size_t expected =
            static_cast<std::size_t>(image->width) * image->height * image->channels;
        if (image->width < 0 || image->height < 0 || image->samples.size() != expected) {
            return std::string(which) + " image sample count does not match its size";
        }
    }
    if (test.width != golden.width || test.height != golden.height) {
        return "size mismatch: test is " + std::to_string(test.width) + "x" +
               std::to_string(test.height) + ", golden is " + std::to_string(golden.width) + "x" +
               std::to_string(golden.height);
    }
    return std::nullopt;
}

CompareResult compare_images(const Image& test, const Image& golden,
                             const CompareOptions& options) {
    if (auto why = incompatibility(test, golden)) throw std::invalid_argument(*why);

    const int channels = compared_channels(test, golden);
    const double limit = options.tolerance + kToleranceSlack;
    CompareResult result;
    result.total_pixels = static_cast<std::size_t>(test.width) * test.height;
    double squared_error_rgb = 0.0;

    for (int y = 0; y < test.height; ++y) {
        for (int x = 0; x < test.width; ++x) {
            bool pixel_matches = true;
            for (int c = 0; c < channels; ++c) {
                const double diff = std::abs(double(test.at(x, y, c)) - golden.at(x, y, c));
                if (c < 3) squared_error_rgb += diff * diff;
                result.max_abs_diff = std::max(result.max_abs_diff, diff);
                if (diff > limit) pixel_matches = false;
            }
            if (pixel_matches) ++result.matching_pixels;
        }
    }

    result.match = result.total_pixels == 0
                       ? 1.0
                       : double(result.matching_pixels) / double(result.total_pixels);
    const double samples = 3.0 * double(result.total_pixels);
    const double mse = samples == 0 ? 0.0 : squared_error_rgb / samples;
    result.psnr_db = mse == 0.0 ? std::numeric_limits<double>::infinity()
                                : 10.0 * std::log10(255.0 * 255.0 / mse);
    result.passed = result.match >= options.min_match;
    return result;
}

Image make_diff_image(const Image& test, const Image& golden, const CompareOptions& options) {
    if (auto why = incompatibility(test, golden)) throw std::invalid_argument(*why);

    const int channels = compared_channels(test, golden);
    const double limit = options.tolerance + kToleranceSlack;
    Image diff{test.width, test.height, 3, {}};
    diff.samples.reserve(static_cast<std::size_t>(test.width) * test.height * 3);

    for (int y = 0; y < test.height; ++y) {
        for (int x = 0; x < test.width; ++x) {
            double worst = 0.0;
            for (int c = 0; c < channels; ++c) {
                worst = std::max(worst, std::abs(double(test.at(x, y, c)) - golden.at(x, y, c)));
            }
            float r, g, b;
            if (worst > limit) {
                // Even a difference just over the limit must stand out, so
                // failures start at half brightness.
                r = float(std::min(255.0, 128.0 + worst * 4.0));
                g = b = 0.0f;
            } else {
                const double luma = 0.2126 * golden.at(x, y, 0) + 0.7152 * golden.at(x, y, 1) +
                                    0.0722 * golden.at(x, y, 2);
                r = g = b = float(luma * 0.3);
            }
            diff.samples.insert(diff.samples.end(), {r, g, b});
        }
    }
    return diff;
}

Image box_blur(const Image& image, int radius) {
    if (radius <= 0) return image;
    Image out = image;
    const int c_count = image.channels;
    // Separable: rows, then columns.
    std::vector<float> rows(image.samples.size());
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const int x0 = std::max(0, x - radius), x1 = std::min(image.width - 1, x + radius);
            for (int c = 0; c < c_count; ++c) {
                double sum = 0;
                for (int k = x0; k <= x1; ++k) sum += image.at(k, y, c);
                rows[(static_cast<std::size_t>(y) * image.width + x) * c_count + c] =
                    static_cast<float>(sum / (x1 - x0 + 1));
            }
        }
    }
    for (int y = 0; y < image.height; ++y) {
        const int y0 = std::max(0, y - radius), y1 = std::min(image.height - 1, y + radius);
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < c_count; ++c) {
                double sum = 0;
                for (int k = y0; k <= y1; ++k)
                    sum += rows[(static_cast<std::size_t>(k) * image.width + x) * c_count + c];
                out.samples[(static_cast<std::size_t>(y) * image.width + x) * c_count + c] =
                    static_cast<float>(sum / (y1 - y0 + 1));
            }
        }
    }
    return out;
}

std::string format_result(const CompareResult& result, const CompareOptions& options) {
    char psnr[32];
    if (std::isinf(result.psnr_db)) {
        std::snprintf(psnr, sizeof psnr, "inf");
    } else {
        std::snprintf(psnr, sizeof psnr, "%.2f", result.psnr_db);
    }
    char line[256];
    std::snprintf(line, sizeof line,
                  "match %.6f (%zu of %zu pixels differ by more than %g/255)  psnr %s dB  "
                  "max_diff %.4g/255  min_match %.4g  %s",
                  result.match, result.total_pixels - result.matching_pixels, result.total_pixels,
                  options.tolerance, psnr, result.max_abs_diff, options.min_match,
                  result.passed ? "PASS" : "FAIL");
    return line;
}

}  // namespace frameray::conformance
