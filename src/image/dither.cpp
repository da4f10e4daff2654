#include "image/dither.h"

#include <algorithm>
#include <cmath>

namespace frameray::image {

namespace {

// povray's Bayer matrices, row by row from the top (measured, see the
// header): the level goes up where the value's fraction exceeds M / n^2.
constexpr int kBayer2[2][2] = {{3, 0}, {1, 2}};
constexpr int kBayer3[3][3] = {{6, 3, 7}, {2, 8, 1}, {5, 0, 4}};
constexpr int kBayer4[4][4] = {{15, 3, 12, 0}, {7, 11, 4, 8}, {13, 1, 14, 2}, {5, 9, 6, 10}};

double bayerOffset(Dither d, int x, int y) {
    switch (d) {
        case Dither::Bayer2:
            return kBayer2[y % 2][x % 2] / 4.0;
        case Dither::Bayer3:
            return kBayer3[y % 3][x % 3] / 9.0;
        case Dither::Bayer4:
            return kBayer4[y % 4][x % 4] / 16.0;
        default:
            return 0.5;
    }
}

// A file value in [0,1]; NaN (a scene's NaN light) is black, as in povray.
double clamped(float v) {
    return std::isnan(v) ? 0.0 : std::clamp(static_cast<double>(v), 0.0, 1.0);
}

void floydSteinberg(const EncodedImage& image, double levels, int colourChannels,
                    std::vector<double>& out) {
    const int w = image.width, ch = image.channels;
    // Error for this row and the next, per pixel and channel (one spare
    // pixel either side, so the neighbours need no tests).
    std::vector<double> row(static_cast<size_t>(w + 2) * ch), below(row.size());
    for (int y = 0; y < image.height; ++y) {
        std::fill(below.begin(), below.end(), 0.0);
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < colourChannels; ++c) {
                const size_t i = (static_cast<size_t>(y) * w + x) * ch + c;
                const auto at = [&](int px) { return static_cast<size_t>(px + 1) * ch + c; };
                const double v = clamped(image.values[i]) * levels + row[at(x)];
                const double q = std::clamp(std::floor(v + 0.5), 0.0, levels);
                out[i] = q;
                const double e = v - q;
                row[at(x + 1)] += e * 7 / 16;
                below[at(x - 1)] += e * 3 / 16;
                below[at(x)] += e * 5 / 16;
                below[at(x + 1)] += e * 1 / 16;
            }
        std::swap(row, below);
    }
}

}  // namespace

std::vector<double> quantizeToLevels(const EncodedImage& image, double levels) {
    std::vector<double> out(image.values.size());
    // Alpha (the last of 2 or 4 channels) is never dithered.
    const int ch = image.channels;
    const int colour = ch == 2 || ch == 4 ? ch - 1 : ch;
    for (size_t i = 0; i < out.size(); ++i)
        out[i] = std::floor(clamped(image.values[i]) * levels + 0.5);
    if (image.dither == Dither::None || image.width <= 0) return out;
    if (image.dither == Dither::FloydSteinberg) {
        floydSteinberg(image, levels, colour, out);
        return out;
    }
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const double offset = 1.0 - bayerOffset(image.dither, x, y);
            for (int c = 0; c < colour; ++c) {
                const size_t i = (static_cast<size_t>(y) * image.width + x) * ch + c;
                out[i] = std::min(std::floor(clamped(image.values[i]) * levels + offset), levels);
            }
        }
    return out;
}

}  // namespace frameray::image
