// Colours: linear RGB plus POV-Ray's filter and transmit channels.
#pragma once

#include <algorithm>
#include <cmath>

namespace frameray {

// Light and surface colours in linear light (scene colours after the
// assumed_gamma conversion). Arithmetic is component-wise.
struct RGB {
    double r = 0, g = 0, b = 0;

    constexpr RGB() = default;
    constexpr RGB(double r_, double g_, double b_) : r(r_), g(g_), b(b_) {}
    constexpr explicit RGB(double s) : r(s), g(s), b(s) {}

    constexpr RGB& operator+=(const RGB& o) {
        r += o.r;
        g += o.g;
        b += o.b;
        return *this;
    }
    constexpr RGB& operator*=(const RGB& o) {
        r *= o.r;
        g *= o.g;
        b *= o.b;
        return *this;
    }
    constexpr RGB& operator-=(const RGB& o) {
        r -= o.r;
        g -= o.g;
        b -= o.b;
        return *this;
    }
    constexpr RGB& operator*=(double s) {
        r *= s;
        g *= s;
        b *= s;
        return *this;
    }
    constexpr bool isBlack() const { return r == 0 && g == 0 && b == 0; }
    constexpr double maxComponent() const { return std::max({r, g, b}); }
};

constexpr RGB operator+(RGB a, const RGB& b) {
    return a += b;
}
constexpr RGB operator-(RGB a, const RGB& b) {
    return a -= b;
}
constexpr RGB operator*(RGB a, const RGB& b) {
    return a *= b;
}
constexpr RGB operator*(RGB a, double s) {
    return a *= s;
}
constexpr RGB operator*(double s, RGB a) {
    return a *= s;
}

// POV-Ray's grey of a colour: the weights of its .gray, pigment_pattern,
// image_pattern, bump_map and alpha of filtered light (measured).
inline constexpr double kGreyRed = 0.297, kGreyGreen = 0.589, kGreyBlue = 0.114;
constexpr double grey(double r, double g, double b) {
    return r * kGreyRed + g * kGreyGreen + b * kGreyBlue;
}
constexpr double grey(const RGB& c) {
    return grey(c.r, c.g, c.b);
}
// The same in single precision, products and sums alike, where povray
// computes it so (pigment_pattern, material_map's grey images: measured).
constexpr float greySingle(float r, float g, float b) {
    return r * static_cast<float>(kGreyRed) + g * static_cast<float>(kGreyGreen) +
           b * static_cast<float>(kGreyBlue);
}

// The summed absolute difference of two colours: POV-Ray's test of whether
// two samples differ enough to subdivide (area-light corners, media
// intervals).
inline double summedDifference(const RGB& a, const RGB& b) {
    return std::fabs(a.r - b.r) + std::fabs(a.g - b.g) + std::fabs(a.b - b.b);
}

// A pigment colour: RGB with filter (coloured transparency) and transmit
// (plain transparency), as POV-Ray's rgbft.
struct Color {
    RGB rgb;
    double filter = 0, transmit = 0;

    constexpr Color() = default;
    constexpr Color(const RGB& c, double f = 0, double t = 0) : rgb(c), filter(f), transmit(t) {}
};

}  // namespace frameray
