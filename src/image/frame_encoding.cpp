#include "image/frame_encoding.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace frameray::image {

EncodedImage encodeFrame(int width, int height, const std::vector<float>& rgb,
                         const std::vector<float>& alphaValues, const GammaEncoding& gamma,
                         int bitDepth, const RenderWindow& window) {
    EncodedImage out;
    out.width = width;
    out.height = height;
    const bool alpha = !alphaValues.empty();
    out.channels = alpha ? 4 : 3;
    out.bitDepth = bitDepth;
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
