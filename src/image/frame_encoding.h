// A rendered frame (linear working-space values) to the file values an
// image is written with: gamma encoding, the render window, and alpha.
#pragma once

#include <vector>

#include "image/gamma.h"
#include "image/image_io.h"

namespace frameray::image {

// The render window in 0-based pixel coordinates, end exclusive.
struct RenderWindow {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool full(int width, int height) const {
        return x0 == 0 && y0 == 0 && x1 == width && y1 == height;
    }
};

// `rgb`: 3 floats per pixel, row-major from the top. `alpha`: empty, or
// 1 - transmittance per pixel, rgb then holding what the visible surfaces
// add (premultiplied). Pixels outside `window` are written black (and
// transparent), as povray does; with alpha the colour is written
// un-premultiplied (povray writes encode(colour / alpha), measured).
// `grey` (Grayscale_Output): one channel (two with alpha), povray's grey
// of the encoded colour: 0.297 R' + 0.589 G' + 0.114 B' (measured: povray
// 3.7's 16-bit grey PNG and PPM equal that to within one level, 8-bit PPM
// equals it rounded; it is not a luminance of the linear colour).
EncodedImage encodeFrame(int width, int height, const std::vector<float>& rgb,
                         const std::vector<float>& alpha, const GammaEncoding& gamma, int bitDepth,
                         const RenderWindow& window, bool grey = false);

}  // namespace frameray::image
