// The palette indices of colour-mapped PNG files (colour type 3), which
// OpenImageIO expands to RGB. POV-Ray 3.7 reads such files as palette
// images (measured: material_map picks textures by their index), like GIFs.
#pragma once

#include <filesystem>
#include <optional>

#include "image/gif_decoder.h"

namespace frameray::image {

// The indices and palette of a PNG file when it is colour-mapped; nullopt
// for any other file (not a PNG, or a PNG of another colour type). Throws
// std::runtime_error naming the path when the PNG is damaged.
std::optional<PaletteImage> readPalettePng(const std::filesystem::path& path);

}  // namespace frameray::image
