// An image's pixels as its file stores them: 8 or 16 bits per channel (or
// floats for HDR and EXR files), 1 to 4 channels, or one 8-bit palette
// index per pixel with the palette beside. Image maps, bump maps and
// height fields read these directly, so a 10000 x 10000 grey PNG costs
// 100 MB (one byte a pixel) and not the 4 GB that prepared colours took.
// Immutable once read; shared between every map that uses the file.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace frameray::util {

class PixelBuffer {
  public:
    enum class Sample : std::uint8_t { U8, U16, F32 };

    PixelBuffer() = default;
    // Room for width x height pixels of `channels` samples, not cleared
    // (the decoder fills every row). Throws std::length_error when the
    // size cannot be addressed, std::bad_alloc when memory runs out.
    PixelBuffer(int width, int height, int channels, Sample sample);

    int width() const { return width_; }
    int height() const { return height_; }
    std::size_t pixelCount() const {
        return static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
    }
    Sample sample() const { return sample_; }
    // 8, 16 or 32 (floats).
    int bitDepth() const { return sample_ == Sample::U8 ? 8 : sample_ == Sample::U16 ? 16 : 32; }
    // Samples stored per pixel (1 for palette images).
    int storedChannels() const { return stored_; }
    // Channels of a pixel's colour: 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA
    // (palette images: 3, or 4 when the palette has alpha).
    int channels() const { return palette_.empty() ? stored_ : (paletteAlpha_ ? 4 : 3); }
    bool hasAlpha() const { return channels() == 2 || channels() == 4; }

    // Row y (0 the top) as bytes, storedChannels() samples a pixel, 16-bit
    // and float samples in the machine's byte order.
    std::size_t rowBytes() const { return static_cast<std::size_t>(width_) * pixelBytes(); }
    unsigned char* row(int y) { return data_.get() + static_cast<std::size_t>(y) * rowBytes(); }
    const unsigned char* row(int y) const {
        return data_.get() + static_cast<std::size_t>(y) * rowBytes();
    }
    unsigned char* data() { return data_.get(); }
    const unsigned char* data() const { return data_.get(); }

    // Palette images: the stored samples are 8-bit indices into these RGBA
    // colours (alpha 255 where the file gives none).
    void setPalette(std::vector<std::array<std::uint8_t, 4>> palette, bool hasAlpha);
    bool isPalette() const { return !palette_.empty(); }
    const std::vector<std::array<std::uint8_t, 4>>& palette() const { return palette_; }
    std::uint8_t index(std::size_t pixel) const { return data_[pixel]; }

    // Channel c (< channels()) of pixel p (row-major from the top) in
    // [0,1] for integer samples (v * (1 / 255) or v * (1 / 65535)) (through the palette for palette
    // images), as stored for floats.
    float value(std::size_t pixel, int c) const {
        if (!palette_.empty())
            return kByteToUnit[palette_[data_[pixel]][static_cast<std::size_t>(c)]];
        const std::size_t i =
            pixel * static_cast<std::size_t>(stored_) + static_cast<std::size_t>(c);
        switch (sample_) {
            case Sample::U8:
                return kByteToUnit[data_[i]];
            case Sample::U16:
                return static_cast<float>(reinterpret_cast<const std::uint16_t*>(data_.get())[i]) *
                       (1.0f / 65535.0f);
            case Sample::F32:
                break;
        }
        return reinterpret_cast<const float*>(data_.get())[i];
    }
    // The integer level of channel c of pixel p (0..255 or 0..65535; the
    // palette's byte for palette images); floats are scaled to 16 bits.
    std::uint32_t level(std::size_t pixel, int c) const;

  private:
    std::size_t pixelBytes() const {
        return static_cast<std::size_t>(stored_) * static_cast<std::size_t>(bitDepth() / 8);
    }

  public:
    // Byte v as v * (1 / 255) in single precision: OpenImageIO's conversion
    // (one ulp from v / 255 for some v), kept so images read as before.
    static constexpr std::array<float, 256> kByteToUnit = [] {
        std::array<float, 256> table{};
        for (std::size_t v = 0; v < table.size(); ++v)
            table[v] = static_cast<float>(v) * (1.0f / 255.0f);
        return table;
    }();

  private:
    int width_ = 0, height_ = 0, stored_ = 0;
    Sample sample_ = Sample::U8;
    bool paletteAlpha_ = false;
    std::unique_ptr<unsigned char[]> data_;
    std::vector<std::array<std::uint8_t, 4>> palette_;
};

}  // namespace frameray::util
