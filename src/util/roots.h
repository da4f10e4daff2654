// Real roots of polynomials in one variable, for the shapes whose ray
// intersection is a polynomial equation in the ray parameter (torus, poly,
// blob, lathe, sor, prism, sphere_sweep, ...).
//
// Coefficients are always given in increasing power: c[i] multiplies x^i,
// so a degree-n polynomial has n + 1 coefficients c[0] .. c[n]. (povray's
// SDL lists them the other way round; the shapes convert.)
//
// Two families of solvers:
//  - closed forms for degree <= 4 (quadratic, Cardano/trigonometric cubic,
//    Ferrari quartic), each root polished by safeguarded Newton steps on the
//    original coefficients, which restores the precision the closed forms
//    lose to cancellation (tiny roots next to huge ones, clustered roots);
//  - Sturm sequences for any degree up to kMaxPolynomialDegree: the Sturm
//    count isolates every distinct root of an interval, then each isolated
//    root is refined by regula falsi (Illinois variant) when it changes sign
//    and by Sturm-count bisection when it does not (even multiplicity).
//
// Every function reports DISTINCT real roots (a double root once), sorted
// ascending. Thread-safe: no state beyond the caller's buffers.
#pragma once

#include <span>

namespace frameray {

// povray 3.7 accepts poly orders up to 35.
inline constexpr int kMaxPolynomialDegree = 35;

// p(x) by Horner's rule; `c` holds degree + 1 coefficients.
double evaluatePolynomial(std::span<const double> c, double x);
// p(x) and p'(x) together.
void evaluatePolynomialAndSlope(std::span<const double> c, double x, double& value, double& slope);

// All real roots of c0 + c1 x + c2 x^2 (fewer terms when the leading ones
// are zero). `roots` has room for 2; returns the count.
int solveQuadratic(double c0, double c1, double c2, double* roots);
// All real roots of c[0] + ... + c[3] x^3. `roots` has room for 3.
int solveCubic(const double c[4], double* roots);
// All real roots of c[0] + ... + c[4] x^4. `roots` has room for 4.
int solveQuartic(const double c[5], double* roots);

// Distinct real roots in [lo, hi] of the polynomial with coefficients `c`
// (degree c.size() - 1 <= kMaxPolynomialDegree) by Sturm sequences. `lo`
// and `hi` may be infinite: the Cauchy bound replaces them. `roots` has
// room for c.size() - 1 values. Returns the count.
int sturmRoots(std::span<const double> c, double lo, double hi, double* roots);

enum class RootMethod {
    ClosedForm,  // closed forms up to degree 4, Sturm above
    Sturm,       // Sturm sequences at every degree (povray's `sturm`)
};

// Distinct real roots in [lo, hi], sorted, of the polynomial `c`. Leading
// zero coefficients lower the degree. `roots` has room for c.size() - 1
// values. Returns the count.
int realRootsInInterval(std::span<const double> c, double lo, double hi, double* roots,
                        RootMethod method = RootMethod::ClosedForm);

}  // namespace frameray
