// Quantisation of file values to a file's levels, rounded or dithered as
// povray 3.7 dithers (Dither=on, Dither_Method FS, B2, B3, B4).
//
// Measured with povray 3.7.0.10 on flat colours (File_Gamma 1, PPM):
// - Bayer: a pixel at (x mod n, y mod n), counted from the top-left
//   corner, gets level floor(v * levels + 1 - M / n^2) with M from the
//   matrices in dither.cpp; so a value exactly on a level is raised by one
//   where M is 0 (povray writes black as 1 there too).
// - FS: povray's Floyd-Steinberg variant, exact on 16x16 flat fields at
//   File_Gamma 1.0 and 2.2 (rules in dither.cpp): the error is carried in
//   working space, and column 0 takes the error meant for the row above.
// Each colour channel is dithered on its own; alpha is rounded.
#pragma once

#include <vector>

#include "image/image_io.h"

namespace frameray::image {

// The level (0..levels) of each of image.values, as image.dither says.
std::vector<double> quantizeToLevels(const EncodedImage& image, double levels);

}  // namespace frameray::image
