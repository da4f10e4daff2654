#include "image/png_reader.h"

#include <fmt/format.h>
#include <png.h>

#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

namespace frameray::image {

namespace {

struct ErrorText {
    char text[256] = {};
};

// libpng reports errors by longjmp back into the setjmp'ed functions
// below (no C++ exception may cross libpng's C frames); the text is kept.
[[noreturn]] void onError(png_structp png, png_const_charp message) {
    auto* error = static_cast<ErrorText*>(png_get_error_ptr(png));
    std::strncpy(error->text, message, sizeof(error->text) - 1);
    png_longjmp(png, 1);
}

void onWarning(png_structp, png_const_charp) {}

struct Header {
    png_uint_32 width = 0, height = 0;
    int depth = 0, colorType = 0;
    bool transparency = false;  // a tRNS chunk
    double gamma = 0;           // gAMA's exponent, 0 without one
    bool srgb = false;          // an sRGB chunk
};

// The setjmp'ed parts hold only plain data, so a longjmp skips no
// destructor.
bool readHeader(png_structp png, png_infop info, Header& h) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_info(png, info);
    png_get_IHDR(png, info, &h.width, &h.height, &h.depth, &h.colorType, nullptr, nullptr, nullptr);
    h.transparency = png_get_valid(png, info, PNG_INFO_tRNS) != 0;
    double gamma = 0;
    if (png_get_gAMA(png, info, &gamma) && gamma > 0) h.gamma = gamma;
    int intent = 0;
    h.srgb = png_get_sRGB(png, info, &intent) != 0;
    return true;
}

// Sets the transformations (OpenImageIO's: grey widened to 8 bits, tRNS to
// alpha; palette files keep their indices, one byte each) and reads every
// row. 16-bit samples arrive in the machine's (little-endian) order.
bool readRows(png_structp png, png_infop info, const Header& h, png_bytep* rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    if (h.colorType == PNG_COLOR_TYPE_PALETTE) {
        png_set_packing(png);
    } else {
        if (h.depth < 8) png_set_expand_gray_1_2_4_to_8(png);
        if (h.transparency) png_set_tRNS_to_alpha(png);
        if (h.depth == 16) png_set_swap(png);
    }
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    png_read_image(png, rows);
    png_read_end(png, nullptr);
    return true;
}

bool readPalette(png_structp png, png_infop info,
                 std::vector<std::array<std::uint8_t, 4>>& palette) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_colorp colors = nullptr;
    int count = 0;
    if (png_get_PLTE(png, info, &colors, &count) & PNG_INFO_PLTE)
        for (int i = 0; i < count; ++i)
            palette.push_back({colors[i].red, colors[i].green, colors[i].blue, 255});
    png_bytep alpha = nullptr;
    int alphaCount = 0;
    if (png_get_tRNS(png, info, &alpha, &alphaCount, nullptr) & PNG_INFO_tRNS)
        for (int i = 0; i < alphaCount && i < count; ++i)
            palette[static_cast<std::size_t>(i)][3] = alpha[i];
    return true;
}

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

int channelsOf(const Header& h) {
    switch (h.colorType) {
        case PNG_COLOR_TYPE_GRAY:
            return h.transparency ? 2 : 1;
        case PNG_COLOR_TYPE_GRAY_ALPHA:
            return 2;
        case PNG_COLOR_TYPE_RGB:
            return h.transparency ? 4 : 3;
        case PNG_COLOR_TYPE_RGB_ALPHA:
            return 4;
        default:
            return 1;  // palette indices
    }
}

}  // namespace

bool hasPngSignature(const std::filesystem::path& path) {
    std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    unsigned char magic[8] = {};
    return file && std::fread(magic, 1, 8, file.get()) == 8 && png_sig_cmp(magic, 0, 8) == 0;
}

SourceImage readPng(const std::filesystem::path& path) {
    std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file)
        throw std::runtime_error(
            fmt::format("cannot read '{}': {}", path.string(), std::strerror(errno)));
    ErrorText error;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, onError, onWarning);
    if (!png) throw std::bad_alloc();
    png_infop info = png_create_info_struct(png);
    struct Cleanup {
        png_structp& png;
        png_infop& info;
        ~Cleanup() { png_destroy_read_struct(&png, info ? &info : nullptr, nullptr); }
    } cleanup{png, info};
    if (!info) throw std::bad_alloc();
    // Images up to povray's own limits, not libpng's default 1 000 000.
    png_set_user_limits(png, 0x7fffffff, 0x7fffffff);
    png_init_io(png, file.get());

    Header h;
    bool ok = readHeader(png, info, h);
    SourceImage src;
    std::vector<std::array<std::uint8_t, 4>> palette;
    if (ok) {
        const bool deep = h.depth == 16 && h.colorType != PNG_COLOR_TYPE_PALETTE;
        auto pixels = std::make_shared<util::PixelBuffer>(
            static_cast<int>(h.width), static_cast<int>(h.height), channelsOf(h),
            deep ? util::PixelBuffer::Sample::U16 : util::PixelBuffer::Sample::U8);
        std::vector<png_bytep> rows(h.height);
        for (png_uint_32 y = 0; y < h.height; ++y) rows[y] = pixels->row(static_cast<int>(y));
        ok = readRows(png, info, h, rows.data());
        if (ok && h.colorType == PNG_COLOR_TYPE_PALETTE) {
            ok = readPalette(png, info, palette);
            if (ok) pixels->setPalette(std::move(palette), h.transparency);
        }
        src.pixels = std::move(pixels);
        // As OpenImageIO reported it: an sRGB chunk declares no gamma (sRGB
        // is the default), gAMA's 1 / exponent is rounded to 2 decimals.
        if (h.gamma > 0 && !h.srgb)
            src.declaredGamma = static_cast<float>(std::round(100.0 / h.gamma) / 100.0);
        src.declaresSrgb = h.srgb;
    }
    if (!ok)
        throw std::runtime_error(fmt::format("cannot read '{}': {}", path.string(), error.text));
    return src;
}

}  // namespace frameray::image
