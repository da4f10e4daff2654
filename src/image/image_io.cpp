#include "image/image_io.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace frameray::image {

namespace fs = std::filesystem;

namespace {

struct TypeInfo {
    FileType type;
    const char* oiioFormat;
    const char* extension;
};
constexpr TypeInfo kTypes[] = {
    {FileType::PNG, "png", ".png"},   {FileType::TGA, "targa", ".tga"},
    {FileType::PPM, "pnm", ".ppm"},   {FileType::EXR, "openexr", ".exr"},
    {FileType::HDR, "hdr", ".hdr"},   {FileType::JPEG, "jpeg", ".jpg"},
    {FileType::TIFF, "tiff", ".tif"}, {FileType::BMP, "bmp", ".bmp"},
};

const TypeInfo& info(FileType t) {
    for (const auto& i : kTypes)
        if (i.type == t) return i;
    return kTypes[0];
}

template <typename T>
std::vector<T> quantize(const std::vector<float>& values, double maxValue) {
    std::vector<T> out(values.size());
    for (size_t i = 0; i < values.size(); ++i) {
        const double v = std::clamp(static_cast<double>(values[i]), 0.0, 1.0);
        out[i] = static_cast<T>(std::floor(v * maxValue + 0.5));
    }
    return out;
}

}  // namespace

const char* extensionFor(FileType type) { return info(type).extension; }

void writeAtomic(const fs::path& path, FileType type, const EncodedImage& image) {
    const TypeInfo& ti = info(type);
    auto out = OIIO::ImageOutput::create(ti.oiioFormat);
    if (!out) throw std::runtime_error(fmt::format("no image writer for {}: {}", ti.oiioFormat, OIIO::geterror()));

    const bool floatFile = type == FileType::EXR || type == FileType::HDR;
    const OIIO::TypeDesc format =
        floatFile ? OIIO::TypeDesc::HALF : (image.bitDepth > 8 ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8);
    OIIO::ImageSpec spec(image.width, image.height, image.channels, format);

    // Unique per process and target, in the same folder so rename is atomic.
    const fs::path tmp = path.parent_path() /
                         fmt::format(".{}.{}.tmp", path.filename().string(), static_cast<long>(getpid()));
    if (!out->open(tmp.string(), spec))
        throw std::runtime_error(fmt::format("cannot write '{}': {}", path.string(), out->geterror()));
    bool ok;
    if (floatFile) {
        ok = out->write_image(OIIO::TypeDesc::FLOAT, image.values.data());
    } else if (image.bitDepth > 8) {
        const auto q = quantize<uint16_t>(image.values, 65535.0);
        ok = out->write_image(OIIO::TypeDesc::UINT16, q.data());
    } else {
        const auto q = quantize<uint8_t>(image.values, 255.0);
        ok = out->write_image(OIIO::TypeDesc::UINT8, q.data());
    }
    const std::string writeError = ok ? std::string() : out->geterror();
    ok = out->close() && ok;
    std::error_code ec;
    if (!ok) {
        fs::remove(tmp, ec);
        throw std::runtime_error(fmt::format("cannot write '{}': {}", path.string(),
                                             writeError.empty() ? out->geterror() : writeError));
    }
    fs::rename(tmp, path, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw std::runtime_error(fmt::format("cannot move the finished frame to '{}': {}", path.string(), ec.message()));
    }
}

EncodedImage read(const fs::path& path) {
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) throw std::runtime_error(fmt::format("cannot read '{}': {}", path.string(), OIIO::geterror()));
    const OIIO::ImageSpec& spec = in->spec();
    EncodedImage img;
    img.width = spec.width;
    img.height = spec.height;
    img.channels = spec.nchannels;
    img.bitDepth = static_cast<int>(spec.format.size() * 8);
    img.values.resize(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img.values.data()))
        throw std::runtime_error(fmt::format("cannot read '{}': {}", path.string(), in->geterror()));
    in->close();
    return img;
}

}  // namespace frameray::image
