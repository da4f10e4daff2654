#include "image/frame_encoding.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "util/color.h"

namespace frameray::image {

namespace {

// Colour file values to povray's grey ones (see encodeFrame).
EncodedImage toGrey(const EncodedImage& colour) {
    EncodedImage out;
    out.width = colour.width;
    out.height = colour.height;
    out.bitDepth = colour.bitDepth;
    out.encoding = colour.encoding;
    const int in = colour.channels;
    out.channels = in == 4 ? 2 : 1;
    const size_t pixels = static_cast<size_t>(colour.width) * colour.height;
    out.values.assign(pixels * out.channels, 0.0f);
    for (size_t p = 0; p < pixels; ++p) {
        const float* c = &colour.values[p * in];
        out.values[p * out.channels] = static_cast<float>(grey(c[0], c[1], c[2]));
        if (in == 4) out.values[p * out.channels + 1] = c[3];
    }
    return out;
}

}  // namespace

EncodedImage encodeFrame(int width, int height, const std::vector<float>& rgb,
                         const std::vector<float>& alphaValues, const GammaEncoding& gamma,
                         int bitDepth, const RenderWindow& window, bool grey) {
    if (grey)
        return toGrey(encodeFrame(width, height, rgb, alphaValues, gamma, bitDepth, window, false));
    EncodedImage out;
    out.width = width;
    out.height = height;
    const bool alpha = !alphaValues.empty();
    out.channels = alpha ? 4 : 3;
    out.bitDepth = bitDepth;
    out.encoding = gamma;
    out.values.resize(static_cast<size_t>(width) * height * out.channels);
    // Rows in parallel: three pow() per pixel are tens of milliseconds a
    // frame, which a still image would otherwise spend on one core.
    tbb::parallel_for(
        tbb::blocked_range<int>(0, height, 16), [&](const tbb::blocked_range<int>& rows) {
            for (int y = rows.begin(); y < rows.end(); ++y)
                for (int x = 0; x < width; ++x) {
                    const bool inside =
                        x >= window.x0 && x < window.x1 && y >= window.y0 && y < window.y1;
                    const size_t pixel = static_cast<size_t>(y) * width + x;
                    float* dst = &out.values[pixel * out.channels];
                    const float a = alpha ? alphaValues[pixel] : 1.0f;
                    for (int c = 0; c < 3; ++c) {
                        const double v = rgb[pixel * 3 + c];
                        dst[c] =
                            !inside ? 0.0f
                            : alpha
                                ? (a > 0 ? static_cast<float>(gamma.encode(std::min(1.0, v / a)))
                                         : 0.0f)
                                : static_cast<float>(gamma.encode(v));
                    }
                    if (alpha) dst[3] = inside ? a : 0.0f;
                }
        });
    return out;
}

}  // namespace frameray::image
