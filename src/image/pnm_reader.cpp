#include "image/pnm_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "image/decode_file.h"

namespace frameray::image {

namespace {

class PnmParser {
  public:
    explicit PnmParser(const std::vector<std::uint8_t>& b) : b_(b) {}

    // A decimal header field (or plain-format sample), after white space
    // and '#' comments.
    long number() {
        skipSpace();
        if (pos_ >= b_.size() || b_[pos_] < '0' || b_[pos_] > '9')
            throw std::runtime_error("malformed PNM file");
        long v = 0;
        while (pos_ < b_.size() && b_[pos_] >= '0' && b_[pos_] <= '9') {
            v = v * 10 + (b_[pos_++] - '0');
            if (v > 1L << 30) throw std::runtime_error("PNM value out of range");
        }
        return v;
    }
    // A plain PBM sample: one digit, white space optional.
    int bit() {
        skipSpace();
        if (pos_ >= b_.size()) throw std::runtime_error("truncated PNM file");
        return b_[pos_++] == '1';
    }
    // The single white-space byte between the header and raw samples.
    void endHeader() { ++pos_; }
    const std::uint8_t* raw(std::size_t n) {
        if (pos_ > b_.size() || b_.size() - pos_ < n)
            throw std::runtime_error("truncated PNM file");
        const std::uint8_t* p = b_.data() + pos_;
        pos_ += n;
        return p;
    }

  private:
    void skipSpace() {
        while (pos_ < b_.size()) {
            if (b_[pos_] == '#') {
                while (pos_ < b_.size() && b_[pos_] != '\n' && b_[pos_] != '\r') ++pos_;
            } else if (std::strchr(" \t\r\n\v\f", b_[pos_]) && b_[pos_] != 0) {
                ++pos_;
            } else {
                break;
            }
        }
    }

    const std::vector<std::uint8_t>& b_;
    std::size_t pos_ = 2;
};

}  // namespace

bool hasPnmSignature(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    char magic[2] = {};
    file.read(magic, 2);
    return file && magic[0] == 'P' && magic[1] >= '1' && magic[1] <= '6';
}

SourceImage decodePnm(const std::vector<std::uint8_t>& b) {
    if (b.size() < 2 || b[0] != 'P' || b[1] < '1' || b[1] > '6')
        throw std::runtime_error("not a PNM file");
    const int kind = b[1] - '0';
    const bool bitmap = kind == 1 || kind == 4, plain = kind <= 3;
    const int channels = (kind == 3 || kind == 6) ? 3 : 1;
    PnmParser in(b);
    const long width = in.number(), height = in.number();
    const long maxValue = bitmap ? 1 : in.number();
    if (width <= 0 || height <= 0 || maxValue <= 0 || maxValue > 65535)
        throw std::runtime_error("PNM header out of range");
    // Bytes up to a maximum of 255, 16 bits above; other maxima scaled to
    // the full range, rounded down (as OpenImageIO read them).
    const bool wide = maxValue > 255;
    const long fullRange = wide ? 65535 : 255;
    auto pixels = std::make_shared<util::PixelBuffer>(
        static_cast<int>(width), static_cast<int>(height), channels,
        wide ? util::PixelBuffer::Sample::U16 : util::PixelBuffer::Sample::U8);
    const std::size_t rowSamples = static_cast<std::size_t>(width) * channels;
    if (!plain) in.endHeader();
    for (int y = 0; y < height; ++y) {
        unsigned char* row = pixels->row(y);
        if (bitmap) {
            // 1 is black; raw rows are packed 8 pixels a byte, padded.
            const std::uint8_t* packed = plain ? nullptr : in.raw((rowSamples + 7) / 8);
            for (std::size_t x = 0; x < rowSamples; ++x) {
                const int bit = plain ? in.bit() : (packed[x / 8] >> (7 - x % 8)) & 1;
                row[x] = bit ? 0 : 255;
            }
            continue;
        }
        const std::uint8_t* data = plain ? nullptr : in.raw(rowSamples * (wide ? 2 : 1));
        for (std::size_t i = 0; i < rowSamples; ++i) {
            long v = plain ? in.number() : wide ? (data[2 * i] << 8) | data[2 * i + 1] : data[i];
            v = std::min(v, maxValue) * fullRange / maxValue;
            if (wide)
                reinterpret_cast<std::uint16_t*>(row)[i] = static_cast<std::uint16_t>(v);
            else
                row[i] = static_cast<std::uint8_t>(v);
        }
    }
    SourceImage src;
    src.pixels = std::move(pixels);
    return src;
}

SourceImage readPnm(const std::filesystem::path& path) {
    return decodeFile(path, decodePnm);
}

}  // namespace frameray::image
