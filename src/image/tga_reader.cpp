#include "image/tga_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <stdexcept>

#include "image/decode_file.h"

namespace frameray::image {

namespace {

struct Header {
    int idLength, mapType, imageType, mapFirst, mapLength, mapEntryBits;
    int width, height, pixelBits, descriptor;
};

int u16(const std::vector<std::uint8_t>& b, std::size_t at) {
    return b[at] | (b[at + 1] << 8);
}

// A 15/16-bit pixel's 5-bit channel widened to 8 bits by repeating its
// high bits.
std::uint8_t widen5(int v) {
    return static_cast<std::uint8_t>((v << 3) | (v >> 2));
}

// One pixel of `bits` bits at `p` as RGBA (grey in all three).
std::array<std::uint8_t, 4> decodePixel(const std::uint8_t* p, int bits, bool grey) {
    if (grey) return {p[0], p[0], p[0], bits == 16 ? p[1] : std::uint8_t{255}};
    switch (bits) {
        case 15:
        case 16: {
            const int v = p[0] | (p[1] << 8);
            return {widen5((v >> 10) & 31), widen5((v >> 5) & 31), widen5(v & 31),
                    static_cast<std::uint8_t>(bits == 16 && (v & 0x8000) ? 255 : 0)};
        }
        case 24:
            return {p[2], p[1], p[0], 255};
        default:
            return {p[2], p[1], p[0], p[3]};
    }
}

}  // namespace

SourceImage decodeTga(const std::vector<std::uint8_t>& b) {
    if (b.size() < 18) throw std::runtime_error("truncated TGA file");
    const Header h{b[0], b[1],       b[2],       u16(b, 3), u16(b, 5),
                   b[7], u16(b, 12), u16(b, 14), b[16],     b[17]};
    const int baseType = h.imageType & ~8;
    const bool rle = (h.imageType & 8) != 0;
    if (baseType < 1 || baseType > 3 || h.width <= 0 || h.height <= 0)
        throw std::runtime_error(fmt::format("unsupported TGA image type {}", h.imageType));
    const bool mapped = baseType == 1, grey = baseType == 3;
    if ((mapped && h.pixelBits != 8) || (grey && h.pixelBits != 8 && h.pixelBits != 16) ||
        (!mapped && !grey && h.pixelBits != 15 && h.pixelBits != 16 && h.pixelBits != 24 &&
         h.pixelBits != 32))
        throw std::runtime_error(fmt::format("unsupported TGA pixel size {}", h.pixelBits));
    std::size_t at = 18 + static_cast<std::size_t>(h.idLength);
    // The colour map, as RGBA.
    std::vector<std::array<std::uint8_t, 4>> map;
    const int entryBytes = (h.mapEntryBits + 7) / 8;
    if (h.mapType == 1) {
        const std::size_t bytes = static_cast<std::size_t>(h.mapLength) * entryBytes;
        if (b.size() < at + bytes) throw std::runtime_error("truncated TGA colour map");
        for (int i = 0; i < h.mapLength; ++i)
            map.push_back(decodePixel(&b[at + static_cast<std::size_t>(i) * entryBytes],
                                      h.mapEntryBits, false));
        at += bytes;
    }
    if (mapped && map.empty()) throw std::runtime_error("TGA colour-mapped image without a map");
    const int sourceBits = mapped ? h.mapEntryBits : h.pixelBits;
    // 16-bit pixels' attribute bit is not read as alpha (as OpenImageIO).
    const int channels = grey ? (h.pixelBits == 16 ? 2 : 1) : (sourceBits == 32 ? 4 : 3);
    auto pixels = std::make_shared<util::PixelBuffer>(h.width, h.height, channels,
                                                      util::PixelBuffer::Sample::U8);
    const int pixelBytes = (h.pixelBits + 7) / 8;
    const bool rightToLeft = (h.descriptor & 0x10) != 0, topDown = (h.descriptor & 0x20) != 0;
    const std::size_t count = pixels->pixelCount();
    std::size_t done = 0;
    auto store = [&](const std::uint8_t* p, std::size_t n) {
        std::array<std::uint8_t, 4> c;
        if (mapped) {
            const int i = p[0] - h.mapFirst;
            c = i >= 0 && i < static_cast<int>(map.size()) ? map[static_cast<std::size_t>(i)]
                                                           : std::array<std::uint8_t, 4>{};
        } else {
            c = decodePixel(p, h.pixelBits, grey);
        }
        for (; n > 0 && done < count; --n, ++done) {
            const int fx = static_cast<int>(done % static_cast<std::size_t>(h.width));
            const int fy = static_cast<int>(done / static_cast<std::size_t>(h.width));
            const int x = rightToLeft ? h.width - 1 - fx : fx;
            const int y = topDown ? fy : h.height - 1 - fy;
            std::uint8_t* out = pixels->row(y) + static_cast<std::size_t>(x) * channels;
            if (grey) {
                out[0] = c[0];
                if (channels == 2) out[1] = c[3];
            } else {
                std::copy_n(c.begin(), channels, out);
            }
        }
    };
    auto need = [&](std::size_t n) {
        if (b.size() - std::min(at, b.size()) < n) throw std::runtime_error("truncated TGA file");
    };
    while (done < count) {
        if (!rle) {
            need(static_cast<std::size_t>(pixelBytes));
            store(&b[at], 1);
            at += static_cast<std::size_t>(pixelBytes);
            continue;
        }
        need(1);
        const int packet = b[at++];
        const std::size_t n = static_cast<std::size_t>(packet & 127) + 1;
        if (packet & 128) {
            need(static_cast<std::size_t>(pixelBytes));
            store(&b[at], n);
            at += static_cast<std::size_t>(pixelBytes);
        } else {
            need(n * static_cast<std::size_t>(pixelBytes));
            for (std::size_t i = 0; i < n; ++i, at += static_cast<std::size_t>(pixelBytes))
                store(&b[at], 1);
        }
    }
    SourceImage src;
    src.pixels = std::move(pixels);
    return src;
}

SourceImage readTga(const std::filesystem::path& path) {
    return decodeFile(path, decodeTga);
}

}  // namespace frameray::image
