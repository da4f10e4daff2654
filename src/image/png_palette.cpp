#include "image/png_palette.h"

#include <png.h>

#include <csetjmp>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace frameray::image {

namespace {

struct Input {
    const std::vector<uint8_t>* bytes;
    std::size_t offset;
    char error[256];
};

void readBytes(png_structp png, png_bytep data, png_size_t length) {
    auto* in = static_cast<Input*>(png_get_io_ptr(png));
    if (in->offset + length > in->bytes->size()) png_error(png, "file truncated");
    std::memcpy(data, in->bytes->data() + in->offset, length);
    in->offset += length;
}

// libpng reports errors by longjmp back to readPalettePng (no C++
// exception may cross libpng's C frames); the message is kept.
[[noreturn]] void onError(png_structp png, png_const_charp message) {
    auto* in = static_cast<Input*>(png_get_error_ptr(png));
    std::strncpy(in->error, message, sizeof(in->error) - 1);
    png_longjmp(png, 1);
}

void onWarning(png_structp, png_const_charp) {}

// The part under setjmp: only plain data lives here, so the longjmp skips
// no destructor. `out` is sized by the caller from the header.
bool decode(png_structp png, png_infop info, PaletteImage& out, std::vector<png_bytep>& rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_packing(png);  // 1, 2 and 4-bit indices become one byte each
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    png_read_image(png, rows.data());
    png_colorp colors = nullptr;
    int count = 0;
    if (png_get_PLTE(png, info, &colors, &count) & PNG_INFO_PLTE)
        for (int i = 0; i < count; ++i)
            out.palette.push_back({colors[i].red, colors[i].green, colors[i].blue});
    return true;
}

bool readHeader(png_structp png, png_infop info, png_uint_32& w, png_uint_32& h, int& type) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_info(png, info);
    int depth = 0;
    png_get_IHDR(png, info, &w, &h, &depth, &type, nullptr, nullptr, nullptr);
    return true;
}

}  // namespace

std::optional<PaletteImage> readPalettePng(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                               std::istreambuf_iterator<char>());
    if (bytes.size() < 8 || png_sig_cmp(bytes.data(), 0, 8) != 0) return std::nullopt;
    // Colour type is byte 25 (IHDR is always the first chunk).
    if (bytes.size() < 26 || bytes[25] != PNG_COLOR_TYPE_PALETTE) return std::nullopt;

    Input in{&bytes, 0, {}};
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &in, onError, onWarning);
    if (!png) throw std::runtime_error("libpng: out of memory");
    png_infop info = png_create_info_struct(png);
    png_set_read_fn(png, &in, readBytes);
    png_uint_32 w = 0, h = 0;
    int type = 0;
    PaletteImage out;
    std::vector<png_bytep> rows;
    bool ok = info && readHeader(png, info, w, h, type);
    if (ok && type == PNG_COLOR_TYPE_PALETTE) {
        out.width = static_cast<int>(w);
        out.height = static_cast<int>(h);
        out.indices.resize(static_cast<std::size_t>(w) * h);
        for (png_uint_32 y = 0; y < h; ++y) rows.push_back(out.indices.data() + std::size_t{y} * w);
        ok = decode(png, info, out, rows);
    }
    png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
    if (!ok) throw std::runtime_error(path.string() + ": " + in.error);
    if (type != PNG_COLOR_TYPE_PALETTE) return std::nullopt;
    return out;
}

}  // namespace frameray::image
