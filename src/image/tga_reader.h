// Targa (TGA) files decoded directly: colour-mapped, true-colour and grey
// images, plain or run-length encoded, 8, 15, 16, 24 and 32 bits per
// pixel, any origin. 16-bit pixels widen their 5-bit channels to 8 bits
// as OpenImageIO does (their attribute bit is not alpha); colour-mapped
// files become RGB(A) (POV-Ray 3.7 has
// no palette TGA images). The unit test image_decoders compares the values
// with OpenImageIO's.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "image/image_io.h"

namespace frameray::image {

// Throws std::runtime_error naming what is wrong.
SourceImage decodeTga(const std::vector<std::uint8_t>& bytes);
// Reads and decodes a file; errors name the path.
SourceImage readTga(const std::filesystem::path& path);

}  // namespace frameray::image
