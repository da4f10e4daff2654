// libframeray_oiio.so: the only code that talks to OpenImageIO (see
// codecs.h for why it is a module loaded at run time).
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "image/codecs.h"

namespace frameray::image {

namespace {

std::vector<unsigned char> encode(const EncodeRequest& r) {
    auto out = OIIO::ImageOutput::create(r.format);
    if (!out)
        throw std::runtime_error(
            fmt::format("no image writer for {}: {}", r.format, OIIO::geterror()));
    const OIIO::TypeDesc type = r.pixelType == PixelType::Half     ? OIIO::TypeDesc::HALF
                                : r.pixelType == PixelType::UInt16 ? OIIO::TypeDesc::UINT16
                                                                   : OIIO::TypeDesc::UINT8;
    OIIO::ImageSpec spec(r.width, r.height, r.channels, type);
    if (r.channels == 4) {
        spec.alpha_channel = 3;
        // The colour is already un-premultiplied (as povray writes alpha);
        // without this the writer would divide it by alpha again.
        spec.attribute("oiio:UnassociatedAlpha", 1);
    }
    if (r.compression) spec.attribute("compression", r.compression);
    // Encoded in memory: the caller writes the file itself, checking every
    // write (OpenImageIO's own writers do not all report a full disk).
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    if (!out->set_ioproxy(&memory) || !out->open(std::string("frame.") + r.format, spec))
        throw std::runtime_error(out->geterror());
    // Half files take floats; the writer converts.
    const OIIO::TypeDesc given = r.pixelType == PixelType::Half ? OIIO::TypeDesc::FLOAT : type;
    bool ok = out->write_image(given, r.pixels);
    const std::string writeError = ok ? std::string() : out->geterror();
    ok = out->close() && ok;
    if (!ok) throw std::runtime_error(writeError.empty() ? out->geterror() : writeError);
    return bytes;
}

// Opens `path` (with `config`) and reads at most `maxChannels` channels as
// floats; the spec is handed to `info`.
template <typename Info>
EncodedImage readFloats(const std::string& path, const OIIO::ImageSpec* config, int maxChannels,
                        Info info) {
    auto in = OIIO::ImageInput::open(path, config);
    if (!in) throw std::runtime_error(fmt::format("cannot read '{}': {}", path, OIIO::geterror()));
    const OIIO::ImageSpec& spec = in->spec();
    EncodedImage img;
    img.width = spec.width;
    img.height = spec.height;
    img.channels = std::min(spec.nchannels, maxChannels);
    img.bitDepth = static_cast<int>(spec.format.size() * 8);
    img.values.resize(static_cast<size_t>(spec.width) * spec.height * img.channels);
    if (!in->read_image(0, 0, 0, img.channels, OIIO::TypeDesc::FLOAT, img.values.data()))
        throw std::runtime_error(fmt::format("cannot read '{}': {}", path, in->geterror()));
    info(spec);
    in->close();
    return img;
}

EncodedImage read(const std::string& path) {
    return readFloats(path, nullptr, 1 << 16, [](const OIIO::ImageSpec&) {});
}

SourceImage readSource(const std::string& path) {
    // Keep alpha as stored: OpenImageIO would otherwise multiply it into
    // the colour of PNG and TGA files.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    SourceImage src;
    // Channels past RGBA (EXR layers) are not needed.
    src.pixels = readFloats(path, &config, 4, [&](const OIIO::ImageSpec& spec) {
        src.declaredGamma = spec.get_float_attribute("oiio:Gamma", 0.0f);
    });
    return src;
}

constexpr CodecTable kTable{encode, read, readSource};

}  // namespace

}  // namespace frameray::image

extern "C" __attribute__((visibility("default"))) const frameray::image::CodecTable*
frameray_oiio_codecs() {
    return &frameray::image::kTable;
}
