// JPEG files read with libjpeg (the library OpenImageIO uses, with the
// same default decoding, so the values are identical): grey or RGB, 8 bits.
#pragma once

#include <filesystem>
#include <optional>

#include "image/image_io.h"

namespace frameray::image {

// True when the file starts with JPEG's SOI marker.
bool hasJpegSignature(const std::filesystem::path& path);

// nullopt for CMYK and YCCK files (left to OpenImageIO, which converts them
// to RGB). Throws std::runtime_error naming the path when the file cannot
// be read or is damaged.
std::optional<SourceImage> readJpeg(const std::filesystem::path& path);

}  // namespace frameray::image
