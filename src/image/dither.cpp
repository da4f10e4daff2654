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

// povray 3.7's Floyd-Steinberg (measured exact on flat colours at File_Gamma
// 1.0 and 2.2, 16x16, 4096 of 4096 pixels):
// - the error is carried in working space, not in file values: a pixel's
//   working value plus the carried error is encoded and rounded to a
//   level, and its error is that sum (clipped to [0,1]) minus the level
//   decoded back to working space;
// - 7/16 of it goes right, 3/16, 5/16, 1/16 to the row below (left,
//   below, right);
// - povray turns its two row buffers when it stores the first pixel's
//   error of a row, after it has read that pixel's carried error: so
//   column 0 of row y receives what was meant for column 0 of row y-1
//   (diffused from row y-2), and what row y-1 sends down to column 0 is
//   lost;
// - sums are kept in single precision, as povray keeps them.
void floydSteinberg(const EncodedImage& image, double levels, int colourChannels,
                    std::vector<double>& out) {
    const int w = image.width, ch = image.channels;
    const GammaEncoding& gamma = image.encoding;
    // Carried error per pixel and channel, for the row being written and
    // the row below; one spare pixel on the left (index 0) and on the right.
    const auto at = [ch](int px, int c) { return static_cast<size_t>(px + 1) * ch + c; };
    std::vector<float> row(static_cast<size_t>(w + 2) * ch), below(row.size());
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < w; ++x) {
            float error[4] = {};
            for (int c = 0; c < colourChannels; ++c) {
                const size_t i = (static_cast<size_t>(y) * w + x) * ch + c;
                const double file = std::isnan(image.values[i]) ? 0.0 : image.values[i];
                const float working = static_cast<float>(gamma.decode(std::max(file, 0.0)));
                const float sum = working + row[at(x, c)];
                const double encoded = std::clamp(gamma.encode(std::max(0.0f, sum)), 0.0, 1.0);
                const double q = std::min(std::floor(encoded * levels + 0.5), levels);
                out[i] = q;
                error[c] =
                    std::clamp(sum, 0.0f, 1.0f) - static_cast<float>(gamma.decode(q / levels));
            }
            if (x == 0) {
                std::swap(row, below);
                std::fill(below.begin(), below.end(), 0.0f);
            }
            for (int c = 0; c < colourChannels; ++c) {
                const double e = error[c];
                row[at(x + 1, c)] += static_cast<float>(e * (7 / 16.0));
                below[at(x - 1, c)] += static_cast<float>(e * (3 / 16.0));
                below[at(x, c)] += static_cast<float>(e * (5 / 16.0));
                below[at(x + 1, c)] += static_cast<float>(e * (1 / 16.0));
            }
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
