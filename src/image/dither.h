// Quantisation of file values to a file's levels, rounded or dithered as
// povray 3.7 dithers (Dither=on, Dither_Method FS, B2, B3, B4).
//
// Measured with povray 3.7.0.10 on flat colours (File_Gamma 1, PPM):
// - Bayer: a pixel at (x mod n, y mod n), counted from the top-left
//   corner, gets level floor(v * levels + 1 - M / n^2) with M from the
//   matrices in dither.cpp; so a value exactly on a level is raised by one
//   where M is 0 (povray writes black as 1 there too).
// - FS: Floyd-Steinberg error diffusion, rows left to right, rounding to
//   the nearest level, 7/16 of the error to the right, 3/16, 5/16, 1/16 to
//   the row below. That equals povray's pixels for some flat colours
//   (100.25 and 100.4 of 255 on 8x6) but not all: povray's own variant
//   carries the error differently (one level apart in a few pixels).
// Each colour channel is dithered on its own; alpha is rounded.
#pragma once

#include <vector>

#include "image/image_io.h"

namespace frameray::image {

// The level (0..levels) of each of image.values, as image.dither says.
std::vector<double> quantizeToLevels(const EncodedImage& image, double levels);

}  // namespace frameray::image
