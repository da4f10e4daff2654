// GIF files as palette images: the colour index of every pixel and the
// palette, which OpenImageIO does not expose (it expands GIFs to RGBA).
// POV-Ray's image maps need the indices for `filter N`, `transmit N` and
// `use_index`. Only the first frame is read.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace frameray::image {

struct PaletteImage {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> indices;  // row-major from the top
    std::vector<std::array<uint8_t, 3>> palette;
};

// Decodes GIF bytes (87a or 89a; interlaced frames de-interlaced). Throws
// std::runtime_error naming what is wrong.
PaletteImage decodeGif(const std::vector<uint8_t>& bytes);

// Reads and decodes a GIF file; errors name the path.
PaletteImage readGif(const std::filesystem::path& path);

}  // namespace frameray::image
