// The boundary to OpenImageIO. OpenImageIO pulls in about 260 shared
// libraries (its format plugins' dependencies); linking them into frameray
// made every process spend ~0.15 s of CPU (0.3 s on a busy machine) in the
// dynamic loader before main. So OpenImageIO lives in a module,
// libframeray_oiio.so (oiio_codecs.cpp), loaded with dlopen the first time
// an image is encoded or read — and early, on a thread of its own, by
// preloadCodecs(), so the load overlaps the first frame's parse.
//
// The module is built by the same compiler from the same tree, so the
// table passes C++ types; only the entry point has C linkage.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image_io.h"

namespace frameray::image {

enum class PixelType { UInt8, UInt16, Half };

// One image to encode: `channels` samples per pixel in `pixels`, already
// quantised to `pixelType` (UInt8/UInt16) or as floats (Half: the file
// stores half floats).
struct EncodeRequest {
    const char* format = "png";  // OpenImageIO's format name
    int width = 0, height = 0, channels = 3;
    PixelType pixelType = PixelType::UInt8;
    const void* pixels = nullptr;
    const char* compression = nullptr;  // e.g. "rle", "none"; null: the format's default
    // Half files only: when not empty, every channel's name; the channels
    // past the first `halfChannels` are stored as 32-bit floats (depth and
    // ids need the precision), a channel named "Z" is the depth channel.
    std::vector<std::string> channelNames;
    int halfChannels = 0;
};

struct CodecTable {
    // The encoded file's bytes. Throws std::runtime_error.
    std::vector<unsigned char> (*encode)(const EncodeRequest& request);
    // Any image OpenImageIO reads, as floats in [0,1]; alpha as stored
    // when `unassociatedAlpha`, else multiplied into the colour. Throws.
    EncodedImage (*read)(const std::string& path, bool unassociatedAlpha);
    // At the file's bit depth (8, 16 bits, else floats), at most 4
    // channels, alpha kept as stored (not multiplied into the colour); the
    // file's declared gamma in `declaredGamma` (0: none). Throws.
    SourceImage (*readSource)(const std::string& path);
};

// Starts loading the module in the background (idempotent).
void preloadCodecs();
// The loaded table; waits for the load. Throws std::runtime_error naming
// the module and dlopen's reason when it cannot be loaded.
const CodecTable& codecs();

}  // namespace frameray::image

// The module's entry point.
extern "C" const frameray::image::CodecTable* frameray_oiio_codecs();
