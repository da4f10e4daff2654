#include "util/pixel_buffer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace frameray::util {

PixelBuffer::PixelBuffer(int width, int height, int channels, Sample sample)
    : width_(width), height_(height), stored_(channels), sample_(sample) {
    if (width <= 0 || height <= 0 || channels < 1 || channels > 4)
        throw std::length_error("image size out of range");
    const std::size_t pixels = pixelCount();
    if (pixels > std::numeric_limits<std::size_t>::max() / pixelBytes())
        throw std::length_error("image too large to address");
    // Not value-initialised: the pages are touched only as rows are decoded.
    data_.reset(new unsigned char[pixels * pixelBytes()]);
}

void PixelBuffer::setPalette(std::vector<std::array<std::uint8_t, 4>> palette, bool hasAlpha) {
    // Every index gets an entry, so a damaged file's stray index reads black.
    palette.resize(256, std::array<std::uint8_t, 4>{0, 0, 0, 255});
    palette_ = std::move(palette);
    paletteAlpha_ = hasAlpha;
}

std::uint32_t PixelBuffer::level(std::size_t pixel, int c) const {
    if (!palette_.empty()) return palette_[data_[pixel]][static_cast<std::size_t>(c)];
    const std::size_t i = pixel * static_cast<std::size_t>(stored_) + static_cast<std::size_t>(c);
    switch (sample_) {
        case Sample::U8:
            return data_[i];
        case Sample::U16:
            return reinterpret_cast<const std::uint16_t*>(data_.get())[i];
        case Sample::F32:
            break;
    }
    const float v = std::clamp(reinterpret_cast<const float*>(data_.get())[i], 0.0f, 1.0f);
    return static_cast<std::uint32_t>(std::lround(v * 65535.0f));
}

}  // namespace frameray::util
