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
#include "image/jpeg_reader.h"
#include "image/png_reader.h"
#include "image/png_writer.h"
#include "image/pnm_reader.h"
#include "image/ppm_writer.h"
#include "image/tga_reader.h"
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

// The colour channels followed by the extra ones, pixel by pixel; names
// the channels in `request` (colour as half floats, the rest as floats).
std::vector<float> withExtraChannels(const EncodedImage& image, EncodeRequest& request) {
    const size_t base = static_cast<size_t>(image.channels), extra = image.extraNames.size();
    const size_t pixels = static_cast<size_t>(image.width) * image.height;
    std::vector<float> out(pixels * (base + extra));
    for (size_t i = 0; i < pixels; ++i) {
        std::copy_n(&image.values[i * base], base, &out[i * (base + extra)]);
        std::copy_n(&image.extraValues[i * extra], extra, &out[i * (base + extra) + base]);
    }
    static constexpr const char* kColour[] = {"R", "G", "B", "A"};
    request.channelNames.clear();
    if (base == 1)
        request.channelNames.push_back("Y");
    else
        for (size_t c = 0; c < base && c < 4; ++c) request.channelNames.push_back(kColour[c]);
    request.channelNames.insert(request.channelNames.end(), image.extraNames.begin(),
                                image.extraNames.end());
    request.halfChannels = static_cast<int>(base);
    request.channels = static_cast<int>(base + extra);
    return out;
}

bool hasDeepChannels(FileType t) {
    return t == FileType::PNG || t == FileType::TIFF;
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
    fs::path tmp = temporaryPathFor(path);
    util::writeFileDurably(
        tmp, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), path);
    return tmp;
}

std::vector<unsigned char> encodeFile(FileType type, const EncodedImage& image,
                                      const fs::path& path) {
    const TypeInfo& ti = info(type);
    if (type == FileType::PPM) {
        const int bits = std::clamp(image.bitDepth, 1, 16);
        return encodePpm(image.width, image.height, image.channels, bits,
                         quantizeToLevels(image, std::ldexp(1.0, bits) - 1.0));
    }
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
    if (type == FileType::EXR && !image.compression.empty())
        request.compression = image.compression.c_str();
    std::vector<uint16_t> samples16;
    std::vector<uint8_t> samples8;
    std::vector<float> layered;
    if (floatFile && !image.extraNames.empty()) {
        layered = withExtraChannels(image, request);
        request.pixelType = PixelType::Half;
        request.pixels = layered.data();
    } else if (floatFile) {
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
                                                  deep ? 16 : 8, request.pixels, image.gamma)
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
    return codecs().read(path.string(), false);
}

namespace {

bool hasGifSignature(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    char magic[4] = {};
    file.read(magic, 4);
    return file && std::string(magic, 4) == "GIF8";
}

bool hasExtension(const fs::path& path, const char* extension) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == extension;
}

SourceImage fromGif(const fs::path& path) {
    PaletteImage gif = readGif(path);
    auto pixels = std::make_shared<util::PixelBuffer>(gif.width, gif.height, 1,
                                                      util::PixelBuffer::Sample::U8);
    std::copy(gif.indices.begin(), gif.indices.end(), pixels->data());
    std::vector<std::array<uint8_t, 4>> palette;
    for (const auto& c : gif.palette) palette.push_back({c[0], c[1], c[2], 255});
    pixels->setPalette(std::move(palette), false);
    SourceImage src;
    src.pixels = std::move(pixels);
    return src;
}

}  // namespace

SourceImage readSource(const fs::path& path) {
    // By signature first (a file's name may not say what it holds), TGA
    // (which has none) by its extension.
    if (hasPngSignature(path)) return readPng(path);
    if (hasGifSignature(path)) return fromGif(path);
    if (hasJpegSignature(path))
        if (auto jpeg = readJpeg(path)) return std::move(*jpeg);
    if (hasPnmSignature(path)) return readPnm(path);
    if (hasExtension(path, ".tga")) return readTga(path);
    return codecs().readSource(path.string());
}

}  // namespace frameray::image
