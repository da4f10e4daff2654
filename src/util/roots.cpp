#include "util/roots.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <numbers>

namespace frameray {

namespace {

// Safeguarded Newton polishing on the original coefficients: a step is kept
// only while it lowers |p|, so a good root is never made worse and a step
// towards a neighbouring root is refused once it stops helping.
double polishRoot(std::span<const double> c, double x) {
    double v, s;
    evaluatePolynomialAndSlope(c, x, v, s);
    for (int i = 0; i < 12 && v != 0 && s != 0; ++i) {
        const double next = x - v / s;
        if (!std::isfinite(next) || next == x) break;
        double nv, ns;
        evaluatePolynomialAndSlope(c, next, nv, ns);
        if (!(std::fabs(nv) < std::fabs(v))) break;
        x = next;
        v = nv;
        s = ns;
    }
    return x;
}

// Sorts, drops non-finite values and merges roots that polishing has pulled
// onto each other (a double root found twice by a closed form).
int sortAndMerge(double* roots, int n) {
    int kept = 0;
    for (int i = 0; i < n; ++i)
        if (std::isfinite(roots[i])) roots[kept++] = roots[i];
    // Insertion sort: n is at most kMaxPolynomialDegree and mostly 1 to 4,
    // where std::sort's call overhead dominates. Equal values keep their
    // order, as std::sort's own insertion pass leaves them at this size.
    for (int i = 1; i < kept; ++i) {
        const double v = roots[i];
        int j = i;
        for (; j > 0 && v < roots[j - 1]; --j) roots[j] = roots[j - 1];
        roots[j] = v;
    }
    int out = 0;
    for (int i = 0; i < kept; ++i) {
        if (out > 0) {
            const double prev = roots[out - 1];
            const double scale = std::max(std::fabs(prev), std::fabs(roots[i]));
            if (roots[i] - prev <= 1e-10 * scale) continue;
        }
        roots[out++] = roots[i];
    }
    return out;
}

// b² - 4ac with the rounding errors of both products added back (Kahan), so
// the sign is right for nearly double roots.
double discriminant(double a, double b, double c) {
    const double bb = b * b;
    const double ac4 = 4 * a * c;
    const double bbError = std::fma(b, b, -bb);
    const double acError = std::fma(4 * a, c, -ac4);
    return (bb - ac4) + (bbError - acError);
}

int solveQuadraticUnpolished(double c0, double c1, double c2, double* roots) {
    if (c2 == 0) {
        if (c1 == 0) return 0;
        roots[0] = -c0 / c1;
        return 1;
    }
    const double disc = discriminant(c2, c1, c0);
    if (disc < 0) return 0;
    if (disc == 0) {
        roots[0] = -c1 / (2 * c2);
        return 1;
    }
    // q = -(b + sign(b) sqrt(D)) / 2 avoids subtracting nearly equal values;
    // the roots are q / a and c / q.
    const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
    if (q == 0) {
        roots[0] = 0;
        return 1;
    }
    roots[0] = q / c2;
    roots[1] = c0 / q;
    if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);
    return 2;
}

// Roots of the monic cubic x³ + a x² + b x + c, unpolished.
int solveMonicCubic(double a, double b, double c, double* roots) {
    const double q = (a * a - 3 * b) / 9;
    const double r = (2 * a * a * a - 9 * a * b + 27 * c) / 54;
    const double q3 = q * q * q;
    const double r2 = r * r;
    const double shift = a / 3;
    if (r2 < q3) {
        // Three real roots: the trigonometric form.
        const double ratio = std::clamp(r / std::sqrt(q3), -1.0, 1.0);
        const double theta = std::acos(ratio);
        const double m = -2 * std::sqrt(q);
        constexpr double kTwoPi = 2 * std::numbers::pi;
        roots[0] = m * std::cos(theta / 3) - shift;
        roots[1] = m * std::cos((theta + kTwoPi) / 3) - shift;
        roots[2] = m * std::cos((theta - kTwoPi) / 3) - shift;
        return 3;
    }
    // One real root by Cardano; the other two (complex, or a double root
    // when the discriminant is zero, or a near-double pair lost to rounding)
    // come from the deflated quadratic.
    const double big = -std::copysign(std::cbrt(std::fabs(r) + std::sqrt(r2 - q3)), r);
    const double small = big != 0 ? q / big : 0;
    const double x = (big + small) - shift;
    roots[0] = x;
    // x³ + a x² + b x + c = (x - x0)(x² + e x + f).
    const double e = a + x;
    const double f = std::fabs(x) > 1 ? -c / x : b + x * e;
    return 1 + solveQuadraticUnpolished(f, e, 1, roots + 1);
}

}  // namespace

double evaluatePolynomial(std::span<const double> c, double x) {
    double v = 0;
    for (std::size_t i = c.size(); i-- > 0;) v = v * x + c[i];
    return v;
}

void evaluatePolynomialAndSlope(std::span<const double> c, double x, double& value, double& slope) {
    double v = 0, s = 0;
    for (std::size_t i = c.size(); i-- > 0;) {
        s = s * x + v;
        v = v * x + c[i];
    }
    value = v;
    slope = s;
}

int solveQuadratic(double c0, double c1, double c2, double* roots) {
    const double c[3] = {c0, c1, c2};
    const int n = solveQuadraticUnpolished(c0, c1, c2, roots);
    for (int i = 0; i < n; ++i) roots[i] = polishRoot(c, roots[i]);
    return sortAndMerge(roots, n);
}

namespace {

// The largest-magnitude value among roots[0..n).
double largestRoot(const double* roots, int n) {
    double best = roots[0];
    for (int i = 1; i < n; ++i)
        if (std::fabs(roots[i]) > std::fabs(best)) best = roots[i];
    return best;
}

// Divides the degree-n polynomial c by (x - r) for r its largest-magnitude
// root, writing the n coefficients of the quotient. Runs from the constant
// term up (backward deflation), which is the stable direction for the
// largest root; the quotient's leading coefficient is c[n] exactly.
void deflateByLargestRoot(const double* c, int n, double r, double* quotient) {
    if (r == 0) {
        for (int i = 0; i < n; ++i) quotient[i] = c[i + 1];
        return;
    }
    quotient[0] = -c[0] / r;
    for (int i = 1; i < n - 1; ++i) quotient[i] = (quotient[i - 1] - c[i]) / r;
    quotient[n - 1] = c[n];
}

}  // namespace

// The closed forms lose small roots to cancellation when roots differ
// greatly in magnitude (and the trigonometric cubic loses close pairs), but
// their largest root is accurate: it is polished, divided out, and the
// remaining roots come from the better-conditioned lower-degree quotient.
int solveCubic(const double c[4], double* roots) {
    if (c[3] == 0) return solveQuadratic(c[0], c[1], c[2], roots);
    const std::span<const double> coeffs(c, 4);
    double first[3];
    const int m = solveMonicCubic(c[2] / c[3], c[1] / c[3], c[0] / c[3], first);
    const double r = polishRoot(coeffs, largestRoot(first, m));
    double quotient[3];
    deflateByLargestRoot(c, 3, r, quotient);
    int n = solveQuadraticUnpolished(quotient[0], quotient[1], quotient[2], roots);
    for (int i = 0; i < n; ++i) roots[i] = polishRoot(coeffs, roots[i]);
    roots[n++] = r;
    return sortAndMerge(roots, n);
}

int solveQuartic(const double c[5], double* roots) {
    if (c[4] == 0) return solveCubic(c, roots);
    const std::span<const double> coeffs(c, 5);
    const double a = c[3] / c[4], b = c[2] / c[4], cc = c[1] / c[4], d = c[0] / c[4];
    // Depressed quartic y⁴ + p y² + q y + r with x = y - a/4.
    const double a2 = a * a;
    const double p = b - 3 * a2 / 8;
    const double q = cc - a * b / 2 + a2 * a / 8;
    const double r = d - a * cc / 4 + a2 * b / 16 - 3 * a2 * a2 / 256;
    const double shift = a / 4;
    int n = 0;
    double ys[4];
    const double scale = std::max({std::fabs(p) * std::fabs(p), std::fabs(r), 1e-300});
    if (q * q <= 1e-28 * scale * std::max(std::fabs(p), std::sqrt(scale))) {
        // Biquadratic: y² = z with z² + p z + r = 0.
        double zs[2];
        const int nz = solveQuadraticUnpolished(r, p, 1, zs);
        for (int i = 0; i < nz; ++i) {
            if (zs[i] < 0) continue;
            const double s = std::sqrt(zs[i]);
            ys[n++] = s;
            if (s != 0) ys[n++] = -s;
        }
    } else {
        // Ferrari: y⁴ + p y² + q y + r = (y² + p/2 + m)² - 2m (y - q/(4m))²
        // for m a root of the resolvent 8m³ + 8p m² + (2p² - 8r) m - q² = 0;
        // its largest root is positive since q != 0.
        const double resolvent[4] = {-q * q, 2 * p * p - 8 * r, 8 * p, 8};
        double ms[3];
        const int nm = solveMonicCubic(p, (p * p - 4 * r) / 4, -q * q / 8, ms);
        double m = ms[0];
        for (int i = 1; i < nm; ++i) m = std::max(m, ms[i]);
        m = polishRoot(resolvent, m);
        if (m > 0) {
            const double s = std::sqrt(2 * m);
            const double t = q / (2 * s);
            n += solveQuadraticUnpolished(p / 2 + m + t, -s, 1, ys + n);
            n += solveQuadraticUnpolished(p / 2 + m - t, s, 1, ys + n);
        }
    }
    if (n == 0) return 0;
    for (int i = 0; i < n; ++i) ys[i] = polishRoot(coeffs, ys[i] - shift);
    const double largest = largestRoot(ys, n);
    double quotient[4];
    deflateByLargestRoot(c, 4, largest, quotient);
    int count = solveCubic(quotient, roots);
    for (int i = 0; i < count; ++i) roots[i] = polishRoot(coeffs, roots[i]);
    roots[count++] = largest;
    return sortAndMerge(roots, count);
}

namespace {

// A polynomial with its coefficients in increasing power, in a fixed
// buffer (no allocation in the per-ray path).
struct FixedPolynomial {
    int degree = -1;  // -1: the zero polynomial
    // Only c[0] .. c[degree] are meaningful: the rest is never cleared (a
    // Sturm sequence is built for every ray that reaches a sturm shape).
    std::array<double, kMaxPolynomialDegree + 1> c;

    double at(double x) const {
        double v = 0;
        for (int i = degree; i >= 0; --i) v = v * x + c[i];
        return v;
    }
    // Scales to max |c| = 1: the signs the Sturm count needs are unchanged
    // and the relative tolerances below make sense.
    void normalize() {
        double m = 0;
        for (int i = 0; i <= degree; ++i) m = std::max(m, std::fabs(c[i]));
        if (m == 0) {
            degree = -1;
            return;
        }
        for (int i = 0; i <= degree; ++i) c[i] /= m;
    }
};

// A remainder coefficient smaller than this times the magnitude of the
// terms that produced it is rounding noise: keeping it would invent sign
// changes (and roots).
constexpr double kRemainderNoise = 64 * DBL_EPSILON;

// r = -(a mod b), the next member of a Sturm sequence.
void negatedRemainder(const FixedPolynomial& a, const FixedPolynomial& b, FixedPolynomial& r) {
    r.degree = a.degree;
    std::copy_n(a.c.begin(), a.degree + 1, r.c.begin());
    std::array<double, kMaxPolynomialDegree + 1> magnitude;
    for (int i = 0; i <= a.degree; ++i) magnitude[i] = std::fabs(a.c[i]);
    const double lead = b.c[b.degree];
    for (int k = a.degree - b.degree; k >= 0; --k) {
        const double f = r.c[k + b.degree] / lead;
        for (int j = 0; j < b.degree; ++j) {
            r.c[k + j] -= f * b.c[j];
            magnitude[k + j] += std::fabs(f * b.c[j]);
        }
        r.c[k + b.degree] = 0;
    }
    r.degree = b.degree - 1;
    for (int i = 0; i <= r.degree; ++i) {
        r.c[i] = -r.c[i];
        if (std::fabs(r.c[i]) <= kRemainderNoise * magnitude[i]) r.c[i] = 0;
    }
    while (r.degree >= 0 && r.c[r.degree] == 0) --r.degree;
}

class SturmSequence {
  public:
    explicit SturmSequence(std::span<const double> coeffs) {
        FixedPolynomial& p0 = seq_[0];
        p0.degree = static_cast<int>(coeffs.size()) - 1;
        std::copy(coeffs.begin(), coeffs.end(), p0.c.begin());
        p0.normalize();
        count_ = 1;
        if (p0.degree < 1) return;
        FixedPolynomial& p1 = seq_[1];
        p1.degree = p0.degree - 1;
        for (int i = 1; i <= p0.degree; ++i) p1.c[i - 1] = i * p0.c[i];
        p1.normalize();
        count_ = 2;
        while (count_ <= p0.degree && seq_[count_ - 1].degree > 0) {
            FixedPolynomial& next = seq_[count_];
            negatedRemainder(seq_[count_ - 2], seq_[count_ - 1], next);
            next.normalize();
            if (next.degree < 0) break;  // the last member is the gcd
            ++count_;
        }
    }

    const FixedPolynomial& polynomial() const { return seq_[0]; }

    // Sign changes along the sequence at x, zeros skipped.
    int signChanges(double x) const {
        int changes = 0;
        double last = 0;
        for (int i = 0; i < count_; ++i) {
            const double v = seq_[i].at(x);
            if (v == 0) continue;
            if (last != 0 && (v < 0) != (last < 0)) ++changes;
            last = v;
        }
        return changes;
    }

  private:
    std::array<FixedPolynomial, kMaxPolynomialDegree + 1> seq_;
    int count_ = 0;
};

bool tooNarrow(double a, double b) {
    const double mid = 0.5 * (a + b);
    return mid <= a || mid >= b || b - a <= 4 * DBL_EPSILON * std::max(std::fabs(a), std::fabs(b));
}

// The root of p in [a, b] where p(a), p(b) have opposite signs: regula falsi
// with the Illinois halving (superlinear near the root), plus a bisection
// step whenever a few interpolation steps have failed to halve the bracket
// (a bracket from the Cauchy bound can be huge, with |p(a)| 1e30 times
// |p(b)|, where regula falsi alone crawls).
double refineBracketed(const FixedPolynomial& p, double a, double b, double fa, double fb) {
    int side = 0;
    double widthAtCheck = b - a;
    for (int i = 0; i < 400 && !tooNarrow(a, b); ++i) {
        double x;
        if (i % 4 == 3 && b - a > 0.5 * widthAtCheck) {
            x = 0.5 * (a + b);
        } else {
            x = (a * fb - b * fa) / (fb - fa);
            if (!(x > a && x < b)) x = 0.5 * (a + b);
        }
        if (i % 4 == 3) widthAtCheck = b - a;
        const double fx = p.at(x);
        if (fx == 0) return x;
        if ((fx < 0) == (fb < 0)) {
            b = x;
            fb = fx;
            if (side == -1) fa *= 0.5;
            side = -1;
        } else {
            a = x;
            fa = fx;
            if (side == 1) fb *= 0.5;
            side = 1;
        }
    }
    return std::fabs(fa) < std::fabs(fb) ? a : b;
}

}  // namespace

int sturmRoots(std::span<const double> coeffs, double lo, double hi, double* roots) {
    while (!coeffs.empty() && coeffs.back() == 0) coeffs = coeffs.first(coeffs.size() - 1);
    const int degree = static_cast<int>(coeffs.size()) - 1;
    if (degree < 1 || !(lo <= hi)) return 0;
    if (degree == 1) {
        const double x = -coeffs[0] / coeffs[1];
        if (x >= lo && x <= hi) {
            roots[0] = x;
            return 1;
        }
        return 0;
    }
    // Cauchy's bound: every root has |x| < 1 + max |c_i / c_n|.
    double bound = 0;
    for (int i = 0; i < degree; ++i) bound = std::max(bound, std::fabs(coeffs[i] / coeffs[degree]));
    bound = 1 + bound;
    lo = std::max(lo, -bound);
    hi = std::min(hi, bound);
    if (!(lo <= hi)) return 0;

    const SturmSequence sturm(coeffs);
    const FixedPolynomial& p = sturm.polynomial();
    int n = 0;
    // The counts give roots in (a, b]; a root at lo itself is taken here.
    if (p.at(lo) == 0) roots[n++] = lo;
    if (lo == hi) return n;

    struct Interval {
        double a, b;
        int changesA, changesB;
    };
    std::array<Interval, 2 * (kMaxPolynomialDegree + 64)> stack;
    int top = 0;
    stack[top++] = {lo, hi, sturm.signChanges(lo), sturm.signChanges(hi)};
    while (top > 0 && n < degree) {
        const Interval iv = stack[--top];
        const int count = iv.changesA - iv.changesB;
        if (count <= 0) continue;
        if (count == 1) {
            const double fa = p.at(iv.a), fb = p.at(iv.b);
            if (fb == 0) {
                roots[n++] = iv.b;
            } else if ((fa < 0) != (fb < 0) && fa != 0) {
                roots[n++] = refineBracketed(p, iv.a, iv.b, fa, fb);
            } else {
                // A root of even multiplicity: no sign change to chase, so
                // bisect on the Sturm count instead.
                double a = iv.a, b = iv.b;
                int changesA = iv.changesA;
                while (!tooNarrow(a, b)) {
                    const double m = 0.5 * (a + b);
                    if (p.at(m) == 0) {
                        a = b = m;
                        break;
                    }
                    const int changesM = sturm.signChanges(m);
                    if (changesA - changesM >= 1) {
                        b = m;
                    } else {
                        a = m;
                        changesA = changesM;
                    }
                }
                roots[n++] = 0.5 * (a + b);
            }
            continue;
        }
        if (tooNarrow(iv.a, iv.b) || top + 2 > static_cast<int>(stack.size())) {
            roots[n++] = 0.5 * (iv.a + iv.b);  // a cluster closer than doubles resolve
            continue;
        }
        const double m = 0.5 * (iv.a + iv.b);
        const int changesM = sturm.signChanges(m);
        stack[top++] = {m, iv.b, changesM, iv.changesB};
        stack[top++] = {iv.a, m, iv.changesA, changesM};
    }
    std::sort(roots, roots + n);
    return n;
}

int realRootsInInterval(std::span<const double> c, double lo, double hi, double* roots,
                        RootMethod method) {
    while (!c.empty() && c.back() == 0) c = c.first(c.size() - 1);
    const int degree = static_cast<int>(c.size()) - 1;
    if (degree < 1) return 0;
    if (method == RootMethod::Sturm || degree > 4) return sturmRoots(c, lo, hi, roots);
    double all[4];
    int n = 0;
    switch (degree) {
        case 1:
            n = solveQuadratic(c[0], c[1], 0, all);
            break;
        case 2:
            n = solveQuadratic(c[0], c[1], c[2], all);
            break;
        case 3:
            n = solveCubic(c.data(), all);
            break;
        default:
            n = solveQuartic(c.data(), all);
            break;
    }
    int kept = 0;
    for (int i = 0; i < n; ++i)
        if (all[i] >= lo && all[i] <= hi) roots[kept++] = all[i];
    return kept;
}

}  // namespace frameray
