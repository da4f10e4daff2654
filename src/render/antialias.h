// Anti-aliasing: which image-plane positions a block of pixels is sampled
// at, and how the samples combine into pixels (seed 003 §3.3.1, and
// POV-Ray 3.7's behaviour where the text is silent).
//
// Both methods work block by block (Render_Block_Size, 32 by default) and
// read nothing outside their block except samples they trace themselves,
// so a block's pixels depend only on the block's position: the image is
// the same whatever the number of threads. Block boundaries do matter
// (method 1 never super-samples the row above or the column left of a
// block), which is why the block layout follows povray's: squares of the
// block size from the render window's top-left corner.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "util/color.h"

namespace frameray::render {

// One traced sample: colour in working space (unclipped) and POV-Ray's
// transmittance (1 where no ray was traced or the background shows through
// with alpha output).
struct PixelSample {
    RGB rgb;
    double transmit = 0;

    PixelSample& operator+=(const PixelSample& o) {
        rgb += o.rgb;
        transmit += o.transmit;
        return *this;
    }
    PixelSample& operator*=(double s) {
        rgb *= s;
        transmit *= s;
        return *this;
    }
};

struct AntialiasSettings {
    // 0: one sample per pixel centre; 1: POV-Ray's non-recursive
    // super-sampling; 2: POV-Ray's adaptive (recursive) super-sampling.
    int method = 0;
    double threshold = 0.3;  // Antialias_Threshold
    int depth = 3;           // Antialias_Depth
    double jitter = 1.0;     // Jitter_Amount in [0,1]; 0 when Jitter is off
    double gamma = 2.5;      // Antialias_Gamma: colours are compared in this space
    // Working space -> linear light, for the comparison (the scene's
    // assumed_gamma; identity when gamma handling is off).
    std::function<double(double)> toLinear = [](double v) { return v; };
};

// The pixel rectangle [x0,x1) x [y0,y1) of one block.
struct PixelBlock {
    int x0, y0, x1, y1;
};

// Traces one sample at POV-Ray image-plane coordinates: (i, j) is the
// centre of pixel column i, row j (counted from the top).
using SampleFunction = std::function<PixelSample(double x, double y)>;

struct AntialiasCounts {
    std::uint64_t supersampledPixels = 0;
    std::uint64_t samples = 0;  // every traced sample, border samples included
};

// Samples one block; returns its pixels row-major.
std::vector<PixelSample> sampleBlock(const PixelBlock& block, const AntialiasSettings& settings,
                                     const SampleFunction& sample, AntialiasCounts& counts);

// The distance POV-Ray compares with the threshold: the sum of absolute
// channel differences (transmittance included) after converting both
// colours to the anti-aliasing gamma.
double antialiasDistance(const PixelSample& a, const PixelSample& b,
                         const AntialiasSettings& settings);

}  // namespace frameray::render
