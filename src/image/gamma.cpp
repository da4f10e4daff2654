#include "image/gamma.h"

#include <cmath>

namespace frameray::image {

GammaEncoding GammaEncoding::forScene(bool assumedGammaSet, double assumedGamma,
                                      double languageVersion, double fileGamma) {
    GammaEncoding g;
    if (fileGamma > 0) {
        g.curve_ = GammaEncoding::Curve::Power;
        g.fileGamma_ = fileGamma;
    }
    if (assumedGammaSet) {
        g.assumedGamma_ = assumedGamma;
    } else if (languageVersion < 3.7 - 1e-9) {
        g.curve_ = GammaEncoding::Curve::Identity;
    }
    return g;
}

double GammaEncoding::toLinear(double v) const {
    if (curve_ == Curve::Identity || assumedGamma_ == 1.0) return v;
    return std::pow(v, assumedGamma_);
}

double GammaEncoding::encode(double v) const {
    if (curve_ == Curve::Identity) return v;
    // Working space -> linear light -> file encoding.
    const double linear = toLinear(v);
    if (curve_ == Curve::Power) return std::pow(linear, 1.0 / fileGamma_);
    return linear <= 0.0031308 ? linear * 12.92 : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

double GammaEncoding::decode(double v) const {
    if (curve_ == Curve::Identity) return v;
    const double linear = curve_ == Curve::Power ? std::pow(v, fileGamma_)
                          : v <= 0.04045         ? v / 12.92
                                                 : std::pow((v + 0.055) / 1.055, 2.4);
    if (assumedGamma_ == 1.0) return linear;
    return std::pow(linear, 1.0 / assumedGamma_);
}

}  // namespace frameray::image
