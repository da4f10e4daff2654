#include "scene/fractals.h"

namespace frameray::scene {

double fractalValue(double x, double y, const FractalSettings& s) {
    const double cx = s.julia ? s.cx : x, cy = s.julia ? s.cy : y;
    double zx = x, zy = y;
    for (int i = 0; i < s.iterations; ++i) {
        // z^exponent by repeated complex multiplication (exponents 2..33).
        double px = zx, py = zy;
        for (int k = 1; k < s.exponent; ++k) {
            const double nx = px * zx - py * zy;
            py = px * zy + py * zx;
            px = nx;
        }
        zx = px + cx;
        zy = py + cy;
        if (zx * zx + zy * zy > 4.0)
            return s.exteriorType == 0 ? s.exteriorFactor : static_cast<double>(i) / s.iterations;
    }
    return s.interiorFactor;  // interior type 0
}

}  // namespace frameray::scene
