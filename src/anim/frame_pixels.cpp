#include "anim/frame_pixels.h"

#include <algorithm>
#include <cmath>

namespace frameray::anim {

namespace {

std::uint8_t toByte(float v) {
    if (!(v > 0)) return 0;  // NaN too
    return static_cast<std::uint8_t>(std::lround(std::min(v, 1.0f) * 255.0f));
}

}  // namespace

Rgb8Image rgb8Of(const image::EncodedImage& file) {
    Rgb8Image out;
    out.width = file.width;
    out.height = file.height;
    const size_t pixels = static_cast<size_t>(file.width) * file.height;
    out.rgb.resize(pixels * 3);
    const size_t n = static_cast<size_t>(file.channels);
    const bool grey = n < 3;
    for (size_t i = 0; i < pixels; ++i)
        for (size_t c = 0; c < 3; ++c)
            out.rgb[i * 3 + c] = toByte(file.values[i * n + (grey ? 0 : c)]);
    return out;
}

Rgb8Image readRgb8(const std::filesystem::path& path) {
    const image::SourceImage source = image::readSource(path);
    const util::PixelBuffer& p = *source.pixels;
    Rgb8Image out;
    out.width = p.width();
    out.height = p.height();
    out.rgb.resize(p.pixelCount() * 3);
    const bool grey = p.channels() < 3;
    for (size_t i = 0; i < p.pixelCount(); ++i)
        for (int c = 0; c < 3; ++c) out.rgb[i * 3 + c] = toByte(p.value(i, grey ? 0 : c));
    return out;
}

Rgb8Image shrinkToFit(const Rgb8Image& image, int maxWidth, int maxHeight) {
    if (image.width <= maxWidth && image.height <= maxHeight) return image;
    const double scale = std::min(static_cast<double>(maxWidth) / image.width,
                                  static_cast<double>(maxHeight) / image.height);
    Rgb8Image out;
    out.width = std::max(1, static_cast<int>(image.width * scale));
    out.height = std::max(1, static_cast<int>(image.height * scale));
    out.rgb.resize(static_cast<size_t>(out.width) * out.height * 3);
    for (int y = 0; y < out.height; ++y) {
        // The source rows and columns this pixel covers (at least one).
        const int y0 = y * image.height / out.height;
        const int y1 = std::max(y0 + 1, (y + 1) * image.height / out.height);
        for (int x = 0; x < out.width; ++x) {
            const int x0 = x * image.width / out.width;
            const int x1 = std::max(x0 + 1, (x + 1) * image.width / out.width);
            unsigned sum[3] = {0, 0, 0};
            for (int sy = y0; sy < y1; ++sy)
                for (int sx = x0; sx < x1; ++sx)
                    for (int c = 0; c < 3; ++c)
                        sum[c] += image.rgb[(static_cast<size_t>(sy) * image.width + sx) * 3 + c];
            const unsigned count = static_cast<unsigned>((y1 - y0) * (x1 - x0));
            for (int c = 0; c < 3; ++c)
                out.rgb[(static_cast<size_t>(y) * out.width + x) * 3 + c] =
                    static_cast<std::uint8_t>((sum[c] + count / 2) / count);
        }
    }
    return out;
}

}  // namespace frameray::anim
