// PNG encoding with libpng, for the frames frameray writes by default.
// Every other format (and every image read) goes through OpenImageIO
// (codecs.h), but loading OpenImageIO's ~260 libraries costs a process
// about 128 MiB of resident memory and 0.1 s of CPU: too much for the
// common case of a sequence of PNG frames (the frame scheduler's memory
// goal is frames in flight x povray's per-frame peak).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace frameray::image {

// The PNG file of an 8- or 16-bit image with 1-4 channels (grey, grey +
// alpha, RGB, RGBA), `samples` row-major from the top. Throws
// std::runtime_error when libpng fails.
// `gamma` is the gamma the samples are encoded with, stated in the file as
// povray 3.7 states its File_Gamma (measured): a gAMA chunk of 1 / gamma,
// and for sRGB (<= 0) gAMA 1 / 2.2 and an sRGB chunk (perceptual intent).
// Without it the file states no gamma.
std::vector<unsigned char> encodePng(int width, int height, int channels, int bitsPerSample,
                                     const void* samples,
                                     std::optional<double> gamma = std::nullopt);

}  // namespace frameray::image
