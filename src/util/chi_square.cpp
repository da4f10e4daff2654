#include "util/chi_square.h"

#include <cmath>

namespace frameray {

namespace {

// P(a, x), the lower regularized incomplete gamma, by its power series
// (converges quickly for x < a + 1).
double lowerSeries(double a, double x) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 1000; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::fabs(term) < std::fabs(sum) * 1e-16) break;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Q(a, x), the upper regularized incomplete gamma, by its continued
// fraction evaluated with the modified Lentz method (for x >= a + 1).
double upperFraction(double a, double x) {
    constexpr double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 1000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::fabs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::fabs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double step = d * c;
        h *= step;
        if (std::fabs(step - 1.0) < 1e-16) break;
    }
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

}  // namespace

double chiSquareUpperTail(double dof, double x) {
    if (!(x > 0) || !(dof > 0)) return 1.0;
    const double a = 0.5 * dof, h = 0.5 * x;
    return h < a + 1.0 ? 1.0 - lowerSeries(a, h) : upperFraction(a, h);
}

double chiSquareUpperTailInverse(double dof, double tail) {
    if (!(tail > 0.0 && tail < 1.0) || !(dof > 0)) return 0.0;
    // The tail falls as x grows: widen, then bisect to double precision.
    double lo = 0.0, hi = dof + 10.0;
    while (chiSquareUpperTail(dof, hi) > tail) hi *= 2.0;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (chiSquareUpperTail(dof, mid) > tail ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace frameray
