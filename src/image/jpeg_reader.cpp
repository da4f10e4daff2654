#include "image/jpeg_reader.h"

#include <fmt/format.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

// jpeglib.h needs FILE and size_t declared first.
#include <jpeglib.h>

namespace frameray::image {

namespace {

struct ErrorManager {
    jpeg_error_mgr base;  // first: libjpeg hands this pointer back
    std::jmp_buf jump;
    char text[JMSG_LENGTH_MAX] = {};
};

// libjpeg's errors longjmp back into the setjmp'ed functions below (no C++
// exception may cross its C frames); the message is kept.
[[noreturn]] void onError(j_common_ptr info) {
    auto* error = reinterpret_cast<ErrorManager*>(info->err);
    (*info->err->format_message)(info, error->text);
    std::longjmp(error->jump, 1);
}

void onMessage(j_common_ptr, int) {}

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

// Plain data only under setjmp, so a longjmp skips no destructor.
bool readHeader(jpeg_decompress_struct& info, ErrorManager& error, std::FILE* file) {
    if (setjmp(error.jump)) return false;
    jpeg_stdio_src(&info, file);
    jpeg_read_header(&info, TRUE);
    return true;
}

bool readRows(jpeg_decompress_struct& info, ErrorManager& error, util::PixelBuffer& pixels) {
    if (setjmp(error.jump)) return false;
    jpeg_start_decompress(&info);
    while (info.output_scanline < info.output_height) {
        JSAMPROW row = pixels.row(static_cast<int>(info.output_scanline));
        jpeg_read_scanlines(&info, &row, 1);
    }
    jpeg_finish_decompress(&info);
    return true;
}

}  // namespace

bool hasJpegSignature(const std::filesystem::path& path) {
    std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    unsigned char magic[3] = {};
    return file && std::fread(magic, 1, 3, file.get()) == 3 && magic[0] == 0xFF &&
           magic[1] == 0xD8 && magic[2] == 0xFF;
}

std::optional<SourceImage> readJpeg(const std::filesystem::path& path) {
    std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file)
        throw std::runtime_error(
            fmt::format("cannot read '{}': {}", path.string(), std::strerror(errno)));
    jpeg_decompress_struct info{};
    ErrorManager error;
    info.err = jpeg_std_error(&error.base);
    error.base.error_exit = onError;
    error.base.emit_message = onMessage;
    jpeg_create_decompress(&info);
    struct Cleanup {
        jpeg_decompress_struct& info;
        ~Cleanup() { jpeg_destroy_decompress(&info); }
    } cleanup{info};
    bool ok = readHeader(info, error, file.get());
    if (ok && (info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK))
        return std::nullopt;
    SourceImage src;
    if (ok) {
        const bool grey = info.jpeg_color_space == JCS_GRAYSCALE;
        info.out_color_space = grey ? JCS_GRAYSCALE : JCS_RGB;
        auto pixels = std::make_shared<util::PixelBuffer>(
            static_cast<int>(info.image_width), static_cast<int>(info.image_height), grey ? 1 : 3,
            util::PixelBuffer::Sample::U8);
        ok = readRows(info, error, *pixels);
        src.pixels = std::move(pixels);
    }
    if (!ok)
        throw std::runtime_error(fmt::format("cannot read '{}': {}", path.string(), error.text));
    return src;
}

}  // namespace frameray::image
