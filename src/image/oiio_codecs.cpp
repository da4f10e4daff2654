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
    if (!r.channelNames.empty()) {
        spec.channelnames = r.channelNames;
        spec.channelformats.assign(r.channels, OIIO::TypeDesc::FLOAT);
        for (int c = 0; c < r.halfChannels && c < r.channels; ++c)
            spec.channelformats[c] = OIIO::TypeDesc::HALF;
        for (int c = 0; c < r.channels; ++c)
            if (r.channelNames[c] == "Z") spec.z_channel = c;
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

// Opens `path`, keeping alpha as stored when `unassociated` (OpenImageIO
// would otherwise multiply it into the colour of PNG and TGA files).
std::unique_ptr<OIIO::ImageInput> openImage(const std::string& path, bool unassociated) {
    OIIO::ImageSpec config;
    if (unassociated) config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) throw std::runtime_error(fmt::format("cannot read '{}': {}", path, OIIO::geterror()));
    return in;
}

EncodedImage read(const std::string& path, bool unassociatedAlpha) {
    auto in = openImage(path, unassociatedAlpha);
    const OIIO::ImageSpec& spec = in->spec();
    EncodedImage img;
    img.width = spec.width;
    img.height = spec.height;
    img.channels = spec.nchannels;
    img.bitDepth = static_cast<int>(spec.format.size() * 8);
    img.values.resize(static_cast<size_t>(spec.width) * spec.height * img.channels);
    if (!in->read_image(0, 0, 0, img.channels, OIIO::TypeDesc::FLOAT, img.values.data()))
        throw std::runtime_error(fmt::format("cannot read '{}': {}", path, in->geterror()));
    in->close();
    return img;
}

SourceImage readSource(const std::string& path) {
    auto in = openImage(path, true);
    const OIIO::ImageSpec& spec = in->spec();
    // At the file's depth: 8 and 16-bit integers as they are, the rest
    // (half, float, 32-bit integers) as floats.
    using Sample = util::PixelBuffer::Sample;
    const Sample sample = spec.format == OIIO::TypeDesc::UINT8    ? Sample::U8
                          : spec.format == OIIO::TypeDesc::UINT16 ? Sample::U16
                                                                  : Sample::F32;
    const OIIO::TypeDesc type = sample == Sample::U8    ? OIIO::TypeDesc::UINT8
                                : sample == Sample::U16 ? OIIO::TypeDesc::UINT16
                                                        : OIIO::TypeDesc::FLOAT;
    // Channels past RGBA (EXR layers) are not needed.
    const int channels = std::min(spec.nchannels, 4);
    auto pixels = std::make_shared<util::PixelBuffer>(spec.width, spec.height, channels, sample);
    if (!in->read_image(0, 0, 0, channels, type, pixels->data()))
        throw std::runtime_error(fmt::format("cannot read '{}': {}", path, in->geterror()));
    SourceImage src;
    src.declaredGamma = spec.get_float_attribute("oiio:Gamma", 0.0f);
    src.pixels = std::move(pixels);
    in->close();
    return src;
}

constexpr CodecTable kTable{encode, read, readSource};

}  // namespace

}  // namespace frameray::image

extern "C" __attribute__((visibility("default"))) const frameray::image::CodecTable*
frameray_oiio_codecs() {
    return &frameray::image::kTable;
}
