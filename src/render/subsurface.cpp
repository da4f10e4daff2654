#include "render/subsurface.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace frameray::render::subsurface {

double fresnelTransmittance(double cosAngle, double eta) {
    const double c = cosAngle;
    const double g = std::sqrt(eta * eta + c * c - 1.0);
    const double a = (g - c) / (g + c);
    const double b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    const double reflected = 0.5 * a * a * (1.0 + b * b);
    return 1.0 - std::clamp(reflected, 0.0, 1.0);
}

double diffuseFresnelReflectance(double eta) {
    if (eta < 1.0) return eta * eta - std::pow(eta, 2.25);
    const double k = 1.0 - 1.0 / eta;
    return (k + 3.0 * std::pow(k, 4.5)) / 4.0;
}

double diffuseReflectance(double A, double alphaPrime) {
    const double root = std::sqrt(3.0 * (1.0 - alphaPrime));
    return alphaPrime / 2.0 * (1.0 + std::exp(-4.0 / 3.0 * A * root)) * std::exp(-root);
}

namespace {

constexpr int kTableSteps = 100;  // povray's table holds Rd = 0, 1/100 .. 1

// The reduced albedo of diffuse reflectance step/100: Rd rises from 0 at
// albedo 0 to 1 at albedo 1, so a bracketed search finds it (to 1e-10 in
// Rd, povray's tolerance).
double tableEntry(int step, double A) {
    if (step <= 0) return 0.0;
    if (step >= kTableSteps) return 1.0;
    const double target = double(step) / kTableSteps;
    double lo = 0.0, hi = 1.0, rdLo = 0.0, rdHi = 1.0;
    double x = target;
    for (int i = 0; i < 200; ++i) {
        // False position, halved toward the middle when one end stalls.
        x = lo + (target - rdLo) / (rdHi - rdLo) * (hi - lo);
        if (i % 3 == 2) x = 0.5 * (lo + hi);
        const double rd = diffuseReflectance(A, x);
        if (std::fabs(rd - target) < 1e-10) break;
        if (rd < target) {
            lo = x;
            rdLo = rd;
        } else {
            hi = x;
            rdHi = rd;
        }
    }
    return x;
}

}  // namespace

double reducedAlbedo(double rd, double ior) {
    const double fdr = diffuseFresnelReflectance(ior);
    const double A = (1.0 + fdr) / (1.0 - fdr);
    const double at = std::clamp(rd, 0.0, 1.0) * kTableSteps;
    const int i0 = static_cast<int>(std::floor(at));
    const int i1 = static_cast<int>(std::ceil(at));
    const double p = at - i0;
    const double v0 = tableEntry(i0, A);
    return i1 == i0 ? v0 : (1.0 - p) * v0 + p * tableEntry(i1, A);
}

double dipole(double distSqr, double sPrime, double a, double A) {
    const double tPrime = sPrime + a;
    const double alphaPrime = sPrime / tPrime;
    const double sigmaTr = std::sqrt(3.0 * a * tPrime);
    const double zr = 1.0 / tPrime;                // the real source's depth
    const double zv = zr * (1.0 + A * 4.0 / 3.0);  // the virtual source's height
    const double dr2 = zr * zr + distSqr, dv2 = zv * zv + distSqr;
    const double dr = std::sqrt(dr2), dv = std::sqrt(dv2);
    const double real = zr * (sigmaTr + 1.0 / dr) * std::exp(-sigmaTr * dr) / dr2;
    const double virt = zv * (sigmaTr + 1.0 / dv) * std::exp(-sigmaTr * dv) / dv2;
    return alphaPrime / (4.0 * std::numbers::pi) * (real + virt);
}

}  // namespace frameray::render::subsurface
