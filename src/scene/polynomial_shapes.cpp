#include "scene/polynomial_shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "scene/shape_math.h"
#include "util/roots.h"

namespace frameray::scene {

namespace detail {

RecentredRay::RecentredRay(const Ray& ray, const Vec3& centre) {
    speed = length(ray.direction);
    if (!(speed > 0) || !std::isfinite(speed)) {
        speed = 0;
        return;
    }
    dir = ray.direction / speed;
    t0 = dot(centre - ray.origin, dir);
    base = ray.origin + dir * t0;
}

}  // namespace detail

namespace {

RootMethod methodFor(bool sturm) {
    return sturm ? RootMethod::Sturm : RootMethod::ClosedForm;
}

// Appends the t of every root s of `c` in [sLo, sHi] that falls strictly
// inside (tMin, tMax).
void keepRoots(std::span<const double> c, double sLo, double sHi, bool sturm,
               const detail::RecentredRay& rr, double tMin, double tMax, std::vector<double>& ts) {
    std::array<double, kMaxPolynomialDegree> roots;
    const int n = realRootsInInterval(c, sLo, sHi, roots.data(), methodFor(sturm));
    for (int i = 0; i < n; ++i) detail::keepIfInRange(rr.tOf(roots[i]), tMin, tMax, ts);
}

}  // namespace

// --- torus -------------------------------------------------------------------

void Torus::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    const detail::RecentredRay rr(ray);
    if (!rr.valid()) return;
    const Vec3& b = rr.base;
    const Vec3& u = rr.dir;
    // Only the chord through the bounding sphere can hold hits; the ray
    // misses it when it passes further than R + r from the centre.
    const double outer = major_ + minor_;
    const double b2 = dot(b, b);
    if (b2 > outer * outer * (1 + 1e-12)) return;
    const double h = std::sqrt(std::max(0.0, outer * outer - b2)) * (1 + 1e-9) + outer * 1e-12;
    const double sLo = std::max(-h, rr.sOf(tMin));
    const double sHi = std::min(h, rr.sOf(tMax));
    if (!(sLo <= sHi)) return;
    // Along p = b + s u with b.u = 0: |p|² = s² + |b|², and
    // x² + z² = a2 s² + a1 s + a0.
    const double R2 = major_ * major_;
    const double a2 = u.x * u.x + u.z * u.z;
    const double a1 = 2 * (b.x * u.x + b.z * u.z);
    const double a0 = b.x * b.x + b.z * b.z;
    // The ray must cross the thick cylinder holding the tube (|y| <= r,
    // R - r <= distance from the axis <= R + r) within the chord, as povray
    // tests before solving: rays through the hole or past the rim skip the
    // quartic. Only a rejection: the roots are sought over the same span.
    const double slack = 1e-9 * outer;
    double s0 = sLo, s1 = sHi;
    if (u.y != 0) {
        double ya = (-minor_ - slack - b.y) / u.y, yb = (minor_ + slack - b.y) / u.y;
        if (ya > yb) std::swap(ya, yb);
        s0 = std::max(s0, ya);
        s1 = std::min(s1, yb);
        if (!(s0 <= s1)) return;
    } else if (std::fabs(b.y) > minor_ + slack) {
        return;
    }
    const auto axisDistance2 = [&](double s) { return (a2 * s + a1) * s + a0; };
    const double hole = std::max(0.0, major_ - minor_ - slack);
    if (std::max(axisDistance2(s0), axisDistance2(s1)) < hole * hole) return;
    const double nearest = a2 > 0 ? std::clamp(-a1 / (2 * a2), s0, s1) : s0;
    if (std::min({axisDistance2(s0), axisDistance2(s1), axisDistance2(nearest)}) >
        (outer + slack) * (outer + slack))
        return;
    const double k = b2 + R2 - minor_ * minor_;
    // (s² + k)² - 4R² (a2 s² + a1 s + a0).
    const double c[5] = {k * k - 4 * R2 * a0, -4 * R2 * a1, 2 * k - 4 * R2 * a2, 0, 1};
    keepRoots(c, sLo, sHi, sturm_, rr, tMin, tMax, ts);
}

Vec3 Torus::normal(const Vec3& p) const {
    // Away from the nearest point of the tube's centre circle: exact, unlike
    // the gradient of the quartic, which loses precision for thin tubes.
    const double rho = std::hypot(p.x, p.z);
    if (rho == 0) return normalize(Vec3(0, p.y, 0) + Vec3(0, 1e-300, 0));
    const Vec3 centre(p.x / rho * major_, 0, p.z / rho * major_);
    return normalize(p - centre);
}

// povray 3.7's torus uv (measured): u the turns around y from -x towards
// +z (the opposite sense of the sphere's), v the turns around the tube as
// image map_type 5.
bool Torus::uv(const Vec3& p, double& u, double& v) const {
    double angle = std::atan2(p.z, -p.x) / (2 * std::numbers::pi);
    if (angle < 0) angle += 1;
    u = angle;
    const double radial = std::hypot(p.x, p.z) - major_;
    double turn = 0.5 + std::atan2(p.y, radial) / (2 * std::numbers::pi);
    if (turn >= 1) turn -= 1;
    v = turn;
    return true;
}

bool Torus::inside(const Vec3& p) const {
    const double rho = std::hypot(p.x, p.z) - major_;
    return rho * rho + p.y * p.y < minor_ * minor_;
}

Bounds Torus::bounds() const {
    const double outer = major_ + minor_;
    return {{-outer, -minor_, -outer}, {outer, minor_, outer}};
}

// --- poly, cubic, quartic ----------------------------------------------------

int PolynomialSurface::coefficientCount(int order) {
    return (order + 1) * (order + 2) * (order + 3) / 6;
}

PolynomialSurface::PolynomialSurface(int order, const std::vector<double>& coefficients, bool sturm,
                                     std::string name)
    : order_(order), sturm_(sturm), name_(std::move(name)) {
    std::size_t index = 0;
    for (int i = order; i >= 0; --i)
        for (int j = order - i; j >= 0; --j)
            for (int k = order - i - j; k >= 0; --k, ++index)
                if (index < coefficients.size() && coefficients[index] != 0)
                    terms_.push_back({i, j, k, coefficients[index]});
    bounds_ = polynomialBounds(terms_);
}

PolynomialSurface PolynomialSurface::withSturm(bool sturm) const {
    PolynomialSurface copy = *this;
    copy.sturm_ = sturm;
    return copy;
}

double PolynomialSurface::value(const Vec3& p) const {
    std::array<double, kMaxPolynomialDegree + 1> px, py, pz;
    px[0] = py[0] = pz[0] = 1;
    for (int n = 1; n <= order_; ++n) {
        px[n] = px[n - 1] * p.x;
        py[n] = py[n - 1] * p.y;
        pz[n] = pz[n - 1] * p.z;
    }
    double v = 0;
    for (const Term& t : terms_) v += t.coefficient * px[t.i] * py[t.j] * pz[t.k];
    return v;
}

Vec3 PolynomialSurface::normal(const Vec3& p) const {
    std::array<double, kMaxPolynomialDegree + 2> px, py, pz;
    px[0] = py[0] = pz[0] = 1;
    for (int n = 1; n <= order_; ++n) {
        px[n] = px[n - 1] * p.x;
        py[n] = py[n - 1] * p.y;
        pz[n] = pz[n - 1] * p.z;
    }
    Vec3 g;
    for (const Term& t : terms_) {
        if (t.i > 0) g.x += t.coefficient * t.i * px[t.i - 1] * py[t.j] * pz[t.k];
        if (t.j > 0) g.y += t.coefficient * t.j * px[t.i] * py[t.j - 1] * pz[t.k];
        if (t.k > 0) g.z += t.coefficient * t.k * px[t.i] * py[t.j] * pz[t.k - 1];
    }
    const double len = length(g);
    return len > 0 ? g / len : Vec3(0, 1, 0);
}

void PolynomialSurface::allHits(const Ray& ray, double tMin, double tMax,
                                std::vector<double>& ts) const {
    // Rays that miss the box miss the surface; for the others the box's
    // stretch of the ray is where the roots are searched (Sturm's
    // bisection then starts there instead of at the Cauchy bound).
    double boxMin = tMin, boxMax = tMax;
    if (!bounds_.surface.clip(ray, boxMin, boxMax)) return;
    const detail::RecentredRay rr(ray);
    if (!rr.valid()) return;
    // Powers of each coordinate along the ray as polynomials in s:
    // (b + s u)^n, built up by repeated multiplication. Only the entries
    // up to the order are written and read (no clearing of the rest: this
    // runs for every ray that reaches the shape).
    using Poly = std::array<double, kMaxPolynomialDegree + 1>;
    std::array<Poly, kMaxPolynomialDegree + 1> powers[3];
    for (int axis = 0; axis < 3; ++axis) {
        auto& pw = powers[axis];
        const double b = rr.base[axis], u = rr.dir[axis];
        pw[0][0] = 1;
        for (int n = 1; n <= order_; ++n) {
            pw[n][0] = pw[n - 1][0] * b;
            for (int m = 1; m < n; ++m) pw[n][m] = pw[n - 1][m - 1] * u + pw[n - 1][m] * b;
            pw[n][n] = pw[n - 1][n - 1] * u;
        }
    }
    Poly c;
    std::fill_n(c.begin(), order_ + 1, 0.0);
    Poly xy;
    int xyI = -1, xyJ = -1;  // the powers xy holds (terms in povray's order share them in runs)
    for (const Term& t : terms_) {
        const Poly& pz = powers[2][t.k];
        // xy = px * py (degree i + j), then times pz.
        if (t.i != xyI || t.j != xyJ) {
            const Poly& px = powers[0][t.i];
            const Poly& py = powers[1][t.j];
            std::fill_n(xy.begin(), t.i + t.j + 1, 0.0);
            for (int m = 0; m <= t.i; ++m)
                for (int n = 0; n <= t.j; ++n) xy[m + n] += px[m] * py[n];
            xyI = t.i;
            xyJ = t.j;
        }
        for (int m = 0; m <= t.i + t.j; ++m)
            for (int n = 0; n <= t.k; ++n) c[m + n] += t.coefficient * xy[m] * pz[n];
    }
    // Leading coefficients that are rounding noise (a ray along a direction
    // where the top-degree part vanishes) would put spurious roots far away
    // and cost the closed forms their precision.
    int degree = order_;
    double scale = 0;
    for (int n = 0; n <= order_; ++n) scale = std::max(scale, std::fabs(c[n]));
    if (scale == 0) return;
    while (degree > 0 && std::fabs(c[degree]) <= 1e-12 * scale) --degree;
    if (degree == 0) return;
    keepRoots(std::span<const double>(c.data(), degree + 1), rr.sOf(boxMin), rr.sOf(boxMax), sturm_,
              rr, tMin, tMax, ts);
}

}  // namespace frameray::scene
