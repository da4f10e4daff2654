// Netpbm files decoded directly: PBM, PGM and PPM, plain (P1-P3) and raw
// (P4-P6). Samples up to 255 are kept as bytes, deeper ones as 16 bits,
// a maximum value other than 255 or 65535 scaled to the full range and
// rounded down, as OpenImageIO read them (the unit test image_decoders
// compares the values). Bitmap 1 is black (0 as a value).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "image/image_io.h"

namespace frameray::image {

// True when the file starts with P1 ... P6.
bool hasPnmSignature(const std::filesystem::path& path);

// Throws std::runtime_error naming what is wrong.
SourceImage decodePnm(const std::vector<std::uint8_t>& bytes);
// Reads and decodes a file; errors name the path.
SourceImage readPnm(const std::filesystem::path& path);

}  // namespace frameray::image
