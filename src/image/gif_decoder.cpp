#include "image/gif_decoder.h"

#include <fmt/format.h>

#include <stdexcept>

#include "image/decode_file.h"

namespace frameray::image {

namespace {

class ByteReader {
  public:
    explicit ByteReader(const std::vector<uint8_t>& bytes) : bytes_(bytes) {}
    uint8_t u8() {
        if (pos_ >= bytes_.size()) throw std::runtime_error("truncated GIF file");
        return bytes_[pos_++];
    }
    int u16() {
        const int lo = u8();
        return lo | (u8() << 8);
    }
    void skip(std::size_t n) {
        if (bytes_.size() - pos_ < n) throw std::runtime_error("truncated GIF file");
        pos_ += n;
    }
    // The data sub-blocks that follow an extension or an image, joined.
    std::vector<uint8_t> subBlocks() {
        std::vector<uint8_t> out;
        for (;;) {
            const uint8_t n = u8();
            if (n == 0) return out;
            if (bytes_.size() - pos_ < n) throw std::runtime_error("truncated GIF file");
            out.insert(out.end(), bytes_.begin() + static_cast<std::ptrdiff_t>(pos_),
                       bytes_.begin() + static_cast<std::ptrdiff_t>(pos_ + n));
            pos_ += n;
        }
    }

  private:
    const std::vector<uint8_t>& bytes_;
    std::size_t pos_ = 0;
};

std::vector<std::array<uint8_t, 3>> readColorTable(ByteReader& in, int flags) {
    std::vector<std::array<uint8_t, 3>> table(std::size_t{1} << ((flags & 7) + 1));
    for (auto& c : table)
        for (auto& v : c) v = in.u8();
    return table;
}

// GIF's variable-width LZW: codes are packed from the least significant
// bit, widths grow from minCodeSize + 1 up to 12 bits as the table fills.
std::vector<uint8_t> decodeLzw(const std::vector<uint8_t>& data, int minCodeSize,
                               std::size_t pixelCount) {
    if (minCodeSize < 2 || minCodeSize > 8) throw std::runtime_error("bad GIF LZW code size");
    const int clear = 1 << minCodeSize, end = clear + 1;
    std::vector<int> prefix(4096, -1);
    std::vector<uint8_t> suffix(4096), first(4096);
    for (int i = 0; i < clear; ++i) {
        suffix[static_cast<std::size_t>(i)] = static_cast<uint8_t>(i);
        first[static_cast<std::size_t>(i)] = static_cast<uint8_t>(i);
    }
    std::vector<uint8_t> out;
    out.reserve(pixelCount);
    std::vector<uint8_t> stack;
    int width = minCodeSize + 1, next = end + 1, previous = -1;
    uint32_t bits = 0;
    int bitCount = 0;
    std::size_t pos = 0;
    while (out.size() < pixelCount) {
        while (bitCount < width) {
            if (pos >= data.size()) return out;  // short data: the rest stays index 0
            bits |= static_cast<uint32_t>(data[pos++]) << bitCount;
            bitCount += 8;
        }
        const int code = static_cast<int>(bits & ((1u << width) - 1));
        bits >>= width;
        bitCount -= width;
        if (code == clear) {
            width = minCodeSize + 1;
            next = end + 1;
            previous = -1;
            continue;
        }
        if (code == end) break;
        if (previous < 0) {
            if (code >= clear) throw std::runtime_error("corrupt GIF data");
            out.push_back(static_cast<uint8_t>(code));
            previous = code;
            continue;
        }
        int walk = code;
        uint8_t head;
        if (code < next) {
            head = first[static_cast<std::size_t>(code)];
        } else if (code == next) {
            // The KwKwK case: the new string is previous + its own first byte.
            head = first[static_cast<std::size_t>(previous)];
            stack.push_back(head);
            walk = previous;
        } else {
            throw std::runtime_error("corrupt GIF data");
        }
        while (walk >= clear) {
            stack.push_back(suffix[static_cast<std::size_t>(walk)]);
            walk = prefix[static_cast<std::size_t>(walk)];
        }
        stack.push_back(static_cast<uint8_t>(walk));
        out.insert(out.end(), stack.rbegin(), stack.rend());
        stack.clear();
        if (next < 4096) {
            prefix[static_cast<std::size_t>(next)] = previous;
            suffix[static_cast<std::size_t>(next)] = head;
            first[static_cast<std::size_t>(next)] = first[static_cast<std::size_t>(previous)];
            ++next;
            if (next == (1 << width) && width < 12) ++width;
        }
        previous = code;
    }
    out.resize(pixelCount, 0);
    return out;
}

}  // namespace

PaletteImage decodeGif(const std::vector<uint8_t>& bytes) {
    ByteReader in(bytes);
    char magic[6];
    for (char& c : magic) c = static_cast<char>(in.u8());
    if (std::string(magic, 6) != "GIF87a" && std::string(magic, 6) != "GIF89a")
        throw std::runtime_error("not a GIF file");
    PaletteImage img;
    img.width = in.u16();
    img.height = in.u16();
    const int screenFlags = in.u8();
    const uint8_t background = in.u8();
    in.u8();  // aspect ratio
    if (img.width <= 0 || img.height <= 0) throw std::runtime_error("GIF image has no pixels");
    if (screenFlags & 0x80) img.palette = readColorTable(in, screenFlags);
    img.indices.assign(static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height),
                       background);
    for (;;) {
        const uint8_t block = in.u8();
        if (block == 0x3B) throw std::runtime_error("GIF file has no image");
        if (block == 0x21) {
            in.u8();  // extension label
            in.subBlocks();
            continue;
        }
        if (block != 0x2C) throw std::runtime_error("corrupt GIF block");
        const int left = in.u16(), top = in.u16(), w = in.u16(), h = in.u16();
        const int flags = in.u8();
        if (flags & 0x80) img.palette = readColorTable(in, flags);
        if (img.palette.empty()) throw std::runtime_error("GIF image has no colour table");
        const int minCodeSize = in.u8();
        const std::vector<uint8_t> frame =
            decodeLzw(in.subBlocks(), minCodeSize, static_cast<std::size_t>(w) * h);
        // Interlaced frames store rows 0, 8, 16..., then 4, 12..., 2, 6...,
        // then the odd rows.
        std::vector<int> rowOrder;
        if (flags & 0x40) {
            for (const auto& [start, step] : {std::pair{0, 8}, {4, 8}, {2, 4}, {1, 2}})
                for (int r = start; r < h; r += step) rowOrder.push_back(r);
        } else {
            for (int r = 0; r < h; ++r) rowOrder.push_back(r);
        }
        for (int i = 0; i < h; ++i) {
            const int y = top + rowOrder[static_cast<std::size_t>(i)];
            if (y < 0 || y >= img.height) continue;
            for (int x = 0; x < w; ++x) {
                const int sx = left + x;
                if (sx < 0 || sx >= img.width) continue;
                img.indices[static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) +
                            static_cast<std::size_t>(sx)] =
                    frame[static_cast<std::size_t>(i) * static_cast<std::size_t>(w) +
                          static_cast<std::size_t>(x)];
            }
        }
        return img;
    }
}

PaletteImage readGif(const std::filesystem::path& path) {
    return decodeFile(path, decodeGif);
}

}  // namespace frameray::image
