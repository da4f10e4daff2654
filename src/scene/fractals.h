// The mandel and julia patterns: escape-time fractals in the pattern's
// x-y plane. Matched to povray 3.7 (values probed through pattern
// functions): z starts at the point (mandel: c = the point; julia: c is
// the pattern's constant), z ← z^exponent + c until |z|² > 4; an escape
// in iteration i (counting from 0) gives i / iterations for exterior type
// 1, the exterior factor for type 0; points that never escape give the
// interior factor (interior type 0).
#pragma once

namespace frameray::scene {

struct FractalSettings {
    bool julia = false;
    double cx = 0, cy = 0;  // julia's constant
    int iterations = 1;
    int exponent = 2;
    int interiorType = 0;
    double interiorFactor = 1;
    int exteriorType = 1;
    double exteriorFactor = 1;
};

// The fractal's raw value at pattern-space (x, y).
double fractalValue(double x, double y, const FractalSettings& s);

}  // namespace frameray::scene
