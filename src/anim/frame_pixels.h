// A frame as 8-bit RGB, for the ways of looking at a sequence: the contact
// sheet's thumbnails (anim/contact_sheet.h) and the preview video's frames
// (anim/preview_video.h). File values as they are (already gamma-encoded
// for display), clipped to [0, 1]; alpha is dropped.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "image/image_io.h"

namespace frameray::anim {

struct Rgb8Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;  // 3 per pixel, row-major from the top
    bool empty() const { return width <= 0 || height <= 0; }
};

// A frame about to be written (its file values).
Rgb8Image rgb8Of(const image::EncodedImage& file);
// A frame file on disk (PNG, JPEG, TGA, PPM directly; others through
// OpenImageIO). Throws std::runtime_error naming the file.
Rgb8Image readRgb8(const std::filesystem::path& path);
// The image shrunk by whole-pixel box averaging to fit in maxWidth x
// maxHeight (never enlarged); the same input gives the same bytes.
Rgb8Image shrinkToFit(const Rgb8Image& image, int maxWidth, int maxHeight);

}  // namespace frameray::anim
