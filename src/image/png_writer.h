// PNG encoding with libpng, for the frames frameray writes by default.
// Every other format (and every image read) goes through OpenImageIO
// (codecs.h), but loading OpenImageIO's ~260 libraries costs a process
// about 128 MiB of resident memory and 0.1 s of CPU: too much for the
// common case of a sequence of PNG frames (the frame scheduler's memory
// goal is frames in flight x povray's per-frame peak).
#pragma once

#include <cstdint>
#include <vector>

namespace frameray::image {

// The PNG file of an 8- or 16-bit image with 1-4 channels (grey, grey +
// alpha, RGB, RGBA), `samples` row-major from the top. Throws
// std::runtime_error when libpng fails.
std::vector<unsigned char> encodePng(int width, int height, int channels, int bitsPerSample,
                                     const void* samples);

}  // namespace frameray::image
