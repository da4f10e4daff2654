#include "image/image_io.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <stdexcept>

#include "image/codecs.h"
#include "image/dither.h"
#include "image/gif_decoder.h"
#include "image/png_palette.h"
#include "image/png_writer.h"
#include "util/durable_file.h"

namespace frameray::image {

namespace fs = std::filesystem;

namespace {

struct TypeInfo {
    FileType type;
    const char* oiioFormat;
    const char* extension;
};
constexpr TypeInfo kTypes[] = {
    {FileType::PNG, "png", ".png"},       {FileType::TGA, "targa", ".tga"},
    {FileType::TGA_RLE, "targa", ".tga"}, {FileType::PPM, "pnm", ".ppm"},
    {FileType::EXR, "openexr", ".exr"},   {FileType::HDR, "hdr", ".hdr"},
    {FileType::JPEG, "jpeg", ".jpg"},     {FileType::TIFF, "tiff", ".tif"},
    {FileType::BMP, "bmp", ".bmp"},
};

const TypeInfo& info(FileType t) {
    for (const auto& i : kTypes)
        if (i.type == t) return i;
    return kTypes[0];
}

// Rounds to `bits` bits, then spreads the levels over the container's
// range (a 5-bit level 14 in an 8-bit channel is 14*255/31 = 115).
// Rounded or dithered as the image says (image/dither.h); NaN is black.
template <typename T>
std::vector<T> quantize(const EncodedImage& image, int bits, double containerMax) {
    const double levels = std::ldexp(1.0, bits) - 1.0;
    const std::vector<double> q = quantizeToLevels(image, levels);
    std::vector<T> out(q.size());
    for (size_t i = 0; i < q.size(); ++i)
        out[i] = static_cast<T>(std::floor(q[i] * containerMax / levels + 0.5));
    return out;
}

bool hasDeepChannels(FileType t) {
    return t == FileType::PNG || t == FileType::PPM || t == FileType::TIFF;
}

}  // namespace

const char* extensionFor(FileType type) {
    return info(type).extension;
}

fs::path temporaryPathFor(const fs::path& path) {
    return path.parent_path() /
           fmt::format(".{}.{}.tmp", path.filename().string(), static_cast<long>(getpid()));
}

bool parseTemporaryName(const std::string& name, std::string& target, long& pid) {
    // ".TARGET.PID.tmp"
    if (name.size() < 8 || name[0] != '.' || name.compare(name.size() - 4, 4, ".tmp") != 0)
        return false;
    const std::string rest = name.substr(1, name.size() - 5);  // "TARGET.PID"
    const auto dot = rest.rfind('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == rest.size()) return false;
    const std::string digits = rest.substr(dot + 1);
    if (digits.size() > 18 || digits.find_first_not_of("0123456789") != std::string::npos)
        return false;
    target = rest.substr(0, dot);
    pid = std::stol(digits);
    return true;
}

void writeAtomic(const fs::path& path, FileType type, const EncodedImage& image) {
    commitTemporary(writeTemporary(path, type, image), path);
}

fs::path writeTemporary(const fs::path& path, FileType type, const EncodedImage& image) {
    const std::vector<unsigned char> bytes = encodeFile(type, image, path);
    // Unique per process and target, in the same folder so the rename is
    // atomic; on the device before it is renamed and journalled, so a frame
    // the journal calls finished survives a power cut.
    const fs::path tmp = temporaryPathFor(path);
    util::writeFileDurably(
        tmp, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), path);
    return tmp;
}

std::vector<unsigned char> encodeFile(FileType type, const EncodedImage& image,
                                      const fs::path& path) {
    const TypeInfo& ti = info(type);
    const bool floatFile = type == FileType::EXR || type == FileType::HDR;
    const int bits = std::clamp(image.bitDepth, 1, hasDeepChannels(type) ? 16 : 8);
    const bool deep = bits > 8;
    EncodeRequest request;
    request.format = ti.oiioFormat;
    request.width = image.width;
    request.height = image.height;
    request.channels = image.channels;
    if (type == FileType::TGA_RLE) request.compression = "rle";
    if (type == FileType::TGA) request.compression = "none";
    std::vector<uint16_t> samples16;
    std::vector<uint8_t> samples8;
    if (floatFile) {
        request.pixelType = PixelType::Half;
        request.pixels = image.values.data();
    } else if (deep) {
        samples16 = quantize<uint16_t>(image, bits, 65535.0);
        request.pixelType = PixelType::UInt16;
        request.pixels = samples16.data();
    } else {
        samples8 = quantize<uint8_t>(image, bits, 255.0);
        request.pixelType = PixelType::UInt8;
        request.pixels = samples8.data();
    }
    std::vector<unsigned char> bytes;
    try {
        // PNG, the default, without loading OpenImageIO (png_writer.h).
        bytes = type == FileType::PNG ? encodePng(request.width, request.height, request.channels,
                                                  deep ? 16 : 8, request.pixels)
                                      : codecs().encode(request);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(fmt::format("cannot encode '{}': {}", path.string(), e.what()));
    }
    return bytes;
}

void commitTemporary(const fs::path& tmp, const fs::path& path) {
    util::renameDurably(tmp, path);
}

EncodedImage read(const fs::path& path) {
    return codecs().read(path.string());
}

namespace {

bool hasGifSignature(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    char magic[4] = {};
    file.read(magic, 4);
    return file && std::string(magic, 4) == "GIF8";
}

}  // namespace

SourceImage readSource(const fs::path& path) {
    SourceImage src;
    if (hasGifSignature(path)) {
        PaletteImage gif = readGif(path);
        EncodedImage& img = src.pixels;
        img.width = gif.width;
        img.height = gif.height;
        img.channels = 3;
        img.values.reserve(gif.indices.size() * 3);
        for (const uint8_t i : gif.indices) {
            std::array<uint8_t, 3> c{};
            if (i < gif.palette.size()) c = gif.palette[i];
            for (const uint8_t v : c) img.values.push_back(static_cast<float>(v) / 255.0f);
        }
        src.indices = std::move(gif.indices);
        src.palette = std::move(gif.palette);
        return src;
    }
    SourceImage read = codecs().readSource(path.string());
    // Palette PNGs: the colours come from OpenImageIO as for any PNG, the
    // indices from libpng.
    if (auto palette = readPalettePng(path)) {
        if (palette->width == read.pixels.width && palette->height == read.pixels.height) {
            read.indices = std::move(palette->indices);
            read.palette = std::move(palette->palette);
        }
    }
    return read;
}

}  // namespace frameray::image
