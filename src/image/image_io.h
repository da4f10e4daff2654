// Image files through OpenImageIO. Frames are written to a temporary name
// in the destination folder and renamed into place, so a finished frame is
// either complete on disk or absent - never truncated.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace frameray::image {

enum class FileType { PNG, TGA, PPM, EXR, HDR, JPEG, TIFF, BMP };

// File-space values in [0,1], `channels` floats per pixel, row-major from
// the top, quantised to `bitDepth` bits (8 or 16) with round-to-nearest.
struct EncodedImage {
    int width = 0;
    int height = 0;
    int channels = 3;
    int bitDepth = 8;
    std::vector<float> values;
};

const char* extensionFor(FileType type);

// Throws std::runtime_error with the path and reason on failure; the
// destination is untouched then.
void writeAtomic(const std::filesystem::path& path, FileType type, const EncodedImage& image);

// Reads any image OpenImageIO knows as floats in [0,1] (tests, tools).
EncodedImage read(const std::filesystem::path& path);

}  // namespace frameray::image
