// PPM (P6) and PGM (P5) encoding as povray 3.7 writes them: the file's
// maximum value is 2^bits - 1 for any depth from 1 to 16 (measured: +FP5
// writes maxval 31, +FP12 4095, +FP16 65535), samples of one byte up to
// maxval 255 and two bytes (most significant first) above. Without
// OpenImageIO, whose PNM writer knows only 8 and 16 bits.
#pragma once

#include <vector>

namespace frameray::image {

// `levels`: per pixel `channels` values in 0..2^bits-1, row-major from the
// top. Colour images (3 or 4 channels) become P6, grey ones (1 or 2) P5;
// alpha is not written (PPM has none).
std::vector<unsigned char> encodePpm(int width, int height, int channels, int bits,
                                     const std::vector<double>& levels);

}  // namespace frameray::image
