#include "image/png_writer.h"

#include <png.h>

#include <cmath>
#include <csetjmp>
#include <cstring>
#include <stdexcept>
#include <string>

namespace frameray::image {

namespace {

struct Output {
    std::vector<unsigned char>* bytes;
    char error[256];
};

void appendBytes(png_structp png, png_bytep data, png_size_t length) {
    auto* out = static_cast<Output*>(png_get_io_ptr(png));
    out->bytes->insert(out->bytes->end(), data, data + length);
}

void flushNothing(png_structp) {}

// libpng reports errors by longjmp back to encodePng (no C++ exception may
// cross libpng's C frames); the message is kept for the exception.
[[noreturn]] void onError(png_structp png, png_const_charp message) {
    auto* out = static_cast<Output*>(png_get_error_ptr(png));
    std::strncpy(out->error, message, sizeof(out->error) - 1);
    png_longjmp(png, 1);
}

void onWarning(png_structp, png_const_charp) {}

int colorType(int channels) {
    switch (channels) {
        case 1:
            return PNG_COLOR_TYPE_GRAY;
        case 2:
            return PNG_COLOR_TYPE_GRAY_ALPHA;
        case 4:
            return PNG_COLOR_TYPE_RGB_ALPHA;
        default:
            return PNG_COLOR_TYPE_RGB;
    }
}

}  // namespace

std::vector<unsigned char> encodePng(int width, int height, int channels, int bitsPerSample,
                                     const void* samples, std::optional<double> gamma) {
    if (width <= 0 || height <= 0 || channels < 1 || channels > 4 ||
        (bitsPerSample != 8 && bitsPerSample != 16))
        throw std::runtime_error("PNG: unsupported image layout");
    std::vector<unsigned char> bytes;
    Output out{&bytes, {}};
    // Everything the longjmp may skip is made before setjmp.
    const size_t rowBytes = static_cast<size_t>(width) * channels * (bitsPerSample / 8);
    std::vector<png_bytep> rows(static_cast<size_t>(height));
    for (int y = 0; y < height; ++y)
        rows[static_cast<size_t>(y)] = const_cast<png_bytep>(
            static_cast<const unsigned char*>(samples) + rowBytes * static_cast<size_t>(y));
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &out, onError, onWarning);
    if (!png) throw std::runtime_error("PNG: out of memory");
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        throw std::runtime_error("PNG: out of memory");
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        throw std::runtime_error(std::string("PNG: ") + out.error);
    }
    png_set_write_fn(png, &out, appendBytes, flushNothing);
    png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height),
                 bitsPerSample, colorType(channels), PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (gamma) {
        // gAMA holds 100000 / gamma rounded (povray: 1.8 -> 55556).
        const bool srgb = *gamma <= 0;
        const double g = srgb ? 2.2 : *gamma;
        png_set_gAMA_fixed(png, info, static_cast<png_fixed_point>(std::lround(100000.0 / g)));
        if (srgb) png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    }
    png_write_info(png, info);
    // PNG stores 16-bit samples big-endian; ours are in memory order.
    if (bitsPerSample == 16) png_set_swap(png);
    png_write_image(png, rows.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return bytes;
}

}  // namespace frameray::image
