// PNG files read with libpng straight into a PixelBuffer at the file's
// bit depth: 8 or 16 bits, grey, grey + alpha, RGB, RGBA, and palette
// files as indices and palette (POV-Ray 3.7 treats them as palette images:
// material_map picks textures by index, measured). The values are those
// OpenImageIO gave (the unit test image_decoders compares both): grey of 1,
// 2 and 4 bits widened to 8, a tRNS chunk as alpha, and gAMA as the gamma
// the file declares (1 / its exponent to 2 decimals; none with an sRGB
// chunk).
#pragma once

#include <filesystem>

#include "image/image_io.h"

namespace frameray::image {

// True when the file starts with PNG's signature.
bool hasPngSignature(const std::filesystem::path& path);

// Throws std::runtime_error naming the path when the file cannot be read
// or is damaged; std::bad_alloc / std::length_error when it is too large.
SourceImage readPng(const std::filesystem::path& path);

}  // namespace frameray::image
