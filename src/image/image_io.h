// Image files through OpenImageIO. Frames are written to a temporary name
// in the destination folder and renamed into place, so a finished frame is
// either complete on disk or absent - never truncated.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "image/gamma.h"
#include "util/pixel_buffer.h"

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
    // How `values` were encoded from working space: Floyd-Steinberg
    // dithering carries its error in working space, as povray does.
    GammaEncoding encoding = GammaEncoding::identity();
    // EXR only: more channels after the colour (Output_AOVs), stored as
    // 32-bit floats under these names, extraNames.size() per pixel in
    // `extraValues`; and the compression (OpenEXR's codec name, empty: the
    // writer's default).
    std::vector<std::string> extraNames;
    std::vector<float> extraValues;
    std::string compression;
    // The gamma the values are encoded with (File_Gamma, <= 0: sRGB), which
    // a PNG file states in gAMA and sRGB chunks as povray's do (a scene
    // that image_maps the frame decodes it by them); none: unstated.
    std::optional<double> gamma;
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
// file values as stored, at the file's bit depth (alpha not multiplied
// into the colour; palette files as indices and palette), and what the
// file says about its gamma.
struct SourceImage {
    std::shared_ptr<const util::PixelBuffer> pixels;
    // The gamma the file declares (PNG gAMA without an sRGB chunk), 0 when
    // it declares none; declaresSrgb: a PNG sRGB chunk (with or without
    // gAMA), which povray reads as the sRGB curve.
    double declaredGamma = 0;
    bool declaresSrgb = false;
    int width() const { return pixels ? pixels->width() : 0; }
    int height() const { return pixels ? pixels->height() : 0; }
    bool isPalette() const { return pixels && pixels->isPalette(); }
};

// PNG, JPEG, GIF, TGA and PPM/PGM/PBM files are decoded here directly
// (png_reader.h, jpeg_reader.h, gif_decoder.h, tga_reader.h, pnm_reader.h):
// loading OpenImageIO costs ~0.5 s of CPU and ~130 MB. Other formats (TIFF,
// EXR, HDR, BMP, IFF) go through OpenImageIO. Throws std::runtime_error
// with the path and reason.
SourceImage readSource(const std::filesystem::path& path);

}  // namespace frameray::image
