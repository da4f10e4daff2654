// The fractal patterns: mandel, julia and magnet (types 1 and 2, mandel
// and julia forms), escape-time fractals in the pattern's x-y plane.
// Matched to povray 3.7 (values probed through pattern functions):
//  - mandel: z starts at the point p, c = p; julia: z = p, c is the
//    pattern's constant; z ← z^exponent + c until |z|² > 4.
//  - magnet 1: z ← ((z² + c − 1) / (2z + c − 2))²; magnet 2:
//    z ← ((z³ + 3(c−1)z + (c−1)(c−2)) / (3z² + 3(c−2)z + (c−1)(c−2) + 1))²;
//    the mandel form starts at z = 0 with c = p, the julia form at z = p.
//    Both stop when |z|² > 10000 or when z has reached the fixed point 1
//    (|z − 1|² < 0.0001).
// A point that stops in iteration i (from 0) is exterior, one that does
// not stop within the iterations interior; each side has a colouring type
// with a factor f (z is the last point of the orbit):
//   0: f; 1: exterior i / iterations (f unused), interior f · the smallest
//   |z| of the orbit (counting the starting z, except magnet mandel's 0);
//   2: f · Re z; 3: f · Im z; 4: f · (Re z)²; 5: f · (Im z)²;
//   6: exterior f · |z|, interior (Re z)² + f · (Im z)² (povray's, not the
//   documented |z|).
// Defaults: interior type 0, exterior type 1, factors 1.
#pragma once

namespace frameray::scene {

struct FractalSettings {
    enum class Kind { Mandel, Julia, Magnet1Mandel, Magnet1Julia, Magnet2Mandel, Magnet2Julia };
    Kind kind = Kind::Mandel;
    double cx = 0, cy = 0;  // julia's constant
    int iterations = 1;
    int exponent = 2;  // mandel and julia only
    int interiorType = 0;
    double interiorFactor = 1;
    int exteriorType = 1;
    double exteriorFactor = 1;

    bool isMagnet() const { return kind != Kind::Mandel && kind != Kind::Julia; }
};

// The fractal's raw value at pattern-space (x, y).
double fractalValue(double x, double y, const FractalSettings& s);

}  // namespace frameray::scene
