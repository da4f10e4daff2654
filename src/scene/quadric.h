// quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }: the surface
//   A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J = 0,
// inside where the left side is negative (seed 003 §5.2; signs checked
// against povray 3.7).
#pragma once

#include "scene/shapes.h"

namespace frameray::scene {

class Quadric final : public Shape {
  public:
    struct Coefficients {
        double a, b, c, d, e, f, g, h, i, j;
    };
    explicit Quadric(const Coefficients& k) : k_(k) {}
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    Vec3 normal(const Vec3& p) const override;
    bool inside(const Vec3& p) const override { return value(p) < 0; }
    // Unbounded unless the quadric is an ellipsoid; the inside is bounded
    // only when the ellipsoid's inside is its interior.
    Bounds bounds() const override;
    Bounds insideBounds() const override;
    // Quadrics without cross terms (axis-aligned cylinders, cones,
    // hyperboloids, paraboloids) bounded by the box's other axes.
    Bounds insideBoundsWithin(const Bounds& box) const override;
    const char* name() const override { return "quadric"; }

    double value(const Vec3& p) const;

  private:
    // The box around the ellipsoid when the quadratic part is definite;
    // `interiorNegative` tells whether f < 0 inside it.
    bool ellipsoidBounds(Bounds& box, bool& interiorNegative) const;

    Coefficients k_;
};

}  // namespace frameray::scene
