// Shapes whose surface is the zero set of a polynomial in x, y, z, so that
// a ray meets them where a polynomial in the ray parameter vanishes
// (seed 003 §5.2.3.3): the torus, and poly / cubic / quartic with
// arbitrary coefficients. Roots come from util/roots.h: closed forms by
// default, Sturm sequences with `sturm`.
//
// Both solve along the ray in a recentred, unit-speed parameter: the ray
// origin is moved to the ray's point nearest the object-space origin and
// the direction normalised before the polynomial is built. A camera far
// away (or a scene scaled by 1e5) then gives the same well-scaled
// coefficients as a near one, instead of huge ones that cancel.
#pragma once

#include <string>
#include <vector>

#include "scene/polynomial_bounds.h"
#include "scene/shapes.h"

namespace frameray::scene {

namespace detail {

// A ray re-expressed as base + s * dir with dir of unit length and base the
// ray's point nearest `centre` (by default the origin):
// s = t |direction| - t0.
struct RecentredRay {
    Vec3 base;
    Vec3 dir;
    double speed = 0;  // |ray.direction|
    double t0 = 0;     // base = ray.origin + dir * t0

    explicit RecentredRay(const Ray& ray, const Vec3& centre = Vec3(0, 0, 0));
    bool valid() const { return speed > 0; }
    double sOf(double t) const { return t * speed - t0; }
    double tOf(double s) const { return (t0 + s) / speed; }
};

}  // namespace detail

// torus { R, r }: the tube of radius r around the circle of radius R in
// the xz-plane centred at the origin; (|p|² + R² - r²)² = 4R²(x² + z²).
class Torus final : public Shape {
  public:
    Torus(double major, double minor, bool sturm) : major_(major), minor_(minor), sturm_(sturm) {}
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    Vec3 normal(const Vec3& p) const override;
    bool inside(const Vec3& p) const override;
    Bounds bounds() const override;
    const char* name() const override { return "torus"; }
    bool uv(const Vec3& p, double& u, double& v) const override;

    double majorRadius() const { return major_; }
    double minorRadius() const { return minor_; }
    bool sturm() const { return sturm_; }

  private:
    double major_, minor_;
    bool sturm_;
};

// poly { order, <coefficients> }, cubic { <20 coefficients> } and
// quartic { <35 coefficients> }: sum of A x^i y^j z^k = 0, inside where the
// sum is negative. Unbounded for povray; bounded here when the polynomial
// is provably positive far away (polynomial_bounds.h), so that closed
// surfaces (tori written as quartics) join the BVH and rays that miss
// their box skip the root solving; the others search for roots only along
// the box's stretch of the ray.
class PolynomialSurface final : public Shape {
  public:
    // One monomial with its coefficient.
    using Term = PolynomialTerm;

    // The number of coefficients povray reads for an order: one per
    // monomial of degree <= order, (order+1)(order+2)(order+3)/6.
    static int coefficientCount(int order);
    // `coefficients` in povray's order: decreasing power of x, then of y
    // within it, then of z (x^n, x^(n-1)y, x^(n-1)z, x^(n-1), x^(n-2)y², ...,
    // z, constant); verified against povray 3.7 renders.
    PolynomialSurface(int order, const std::vector<double>& coefficients, bool sturm,
                      std::string name);

    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    Vec3 normal(const Vec3& p) const override;
    bool inside(const Vec3& p) const override { return value(p) < 0; }
    Bounds bounds() const override { return bounds_.surface; }
    Bounds insideBounds() const override { return bounds_.inside; }
    const char* name() const override { return name_.c_str(); }

    double value(const Vec3& p) const;
    int order() const { return order_; }
    bool sturm() const { return sturm_; }
    const std::vector<Term>& terms() const { return terms_; }
    PolynomialSurface withSturm(bool sturm) const;

  private:
    PolynomialSurface() = default;
    int order_ = 0;
    std::vector<Term> terms_;  // non-zero terms only
    bool sturm_ = false;
    std::string name_;
    PolynomialBounds bounds_;
};

}  // namespace frameray::scene
