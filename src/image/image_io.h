// Image files through OpenImageIO. Frames are written to a temporary name
// in the destination folder and renamed into place, so a finished frame is
// either complete on disk or absent - never truncated.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace frameray::image {

enum class FileType { PNG, TGA, TGA_RLE, PPM, EXR, HDR, JPEG, TIFF, BMP };

// File-space values in [0,1], `channels` floats per pixel, row-major from
// the top, quantised to `bitDepth` bits (1..16) with round-to-nearest, as
// POV-Ray does: depths up to 8 are stored in 8-bit channels (a 5-bit value
// v is written as v*255/31), deeper ones in 16-bit channels where the
// format has them (PNG, PPM, TIFF) and as 8 bits elsewhere.
// Dither (Dither_Method): how values are quantised to the file's levels
// (image/dither.h).
enum class Dither { None, FloydSteinberg, Bayer2, Bayer3, Bayer4 };

struct EncodedImage {
    int width = 0;
    int height = 0;
    int channels = 3;
    int bitDepth = 8;
    std::vector<float> values;
    Dither dither = Dither::None;
};

const char* extensionFor(FileType type);

// The temporary name writeAtomic uses for `path` in this process: in the
// same folder (so the rename is atomic), hidden, tagged with the process id.
std::filesystem::path temporaryPathFor(const std::filesystem::path& path);
// True when `name` (a file name) is such a temporary file; sets `target`
// to the name of the file it stands for and `pid` to the process that
// wrote it.
bool parseTemporaryName(const std::string& name, std::string& target, long& pid);

// Throws std::runtime_error with the path and reason on failure; the
// destination is untouched then.
void writeAtomic(const std::filesystem::path& path, FileType type, const EncodedImage& image);

// writeAtomic in two steps, so the slow one can run apart from the other:
// writeTemporary encodes the image into temporaryPathFor(path) and flushes
// it to disk (returning that name); commitTemporary renames it into place.
std::filesystem::path writeTemporary(const std::filesystem::path& path, FileType type,
                                     const EncodedImage& image);
void commitTemporary(const std::filesystem::path& temporary, const std::filesystem::path& path);

// The bytes of the file writeTemporary writes (for +O-, standard output);
// `path` names the image in messages.
std::vector<unsigned char> encodeFile(FileType type, const EncodedImage& image,
                                      const std::filesystem::path& path);

// Reads any image OpenImageIO knows as floats in [0,1] (tests, tools).
EncodedImage read(const std::filesystem::path& path);

// An image read to texture a scene (image maps, bump maps, height fields):
// file values as stored, alpha not multiplied into the colour, what the
// file says about its gamma, and for palette files (GIF) the indices.
struct SourceImage {
    // 1 grey, 2 grey + alpha, 3 RGB or 4 RGBA channels in [0,1].
    EncodedImage pixels;
    // The gamma the file declares (PNG gAMA), 0 when it declares none.
    double declaredGamma = 0;
    // Palette images: one index per pixel (row-major from the top) and the
    // palette; `pixels` holds the palette colours too.
    std::vector<uint8_t> indices;
    std::vector<std::array<uint8_t, 3>> palette;
    bool isPalette() const { return !palette.empty(); }
};

// GIF files are decoded as palette images, everything else through
// OpenImageIO. Throws std::runtime_error with the path and reason.
SourceImage readSource(const std::filesystem::path& path);

}  // namespace frameray::image
