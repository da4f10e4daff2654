// Cylinders and cones: shapes of revolution about the axis from a base
// point to a cap point, closed by flat end caps unless `open`
// (seed 003 §5.2: cylinder { base, cap, r [open] },
// cone { base, r1, cap, r2 [open] }).
#pragma once

#include "scene/shapes.h"

namespace frameray::scene {

// The axis both shapes are built around: a point's height along it and its
// offset from it.
struct ShapeAxis {
    ShapeAxis(const Vec3& base, const Vec3& cap);
    Vec3 base;
    Vec3 dir;  // unit, base -> cap
    double length;

    double height(const Vec3& p) const { return dot(p - base, dir); }
    Vec3 offset(const Vec3& p) const {
        const Vec3 w = p - base;
        return w - dir * dot(w, dir);
    }
};

class Cylinder final : public Shape {
public:
    // base != cap and radius > 0 are the caller's to check.
    Cylinder(const Vec3& base, const Vec3& cap, double radius, bool open)
        : axis_(base, cap), radius_(radius), open_(open) {}
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    Vec3 normal(const Vec3& p) const override;
    bool inside(const Vec3& p) const override;
    Bounds bounds() const override;
    const char* name() const override { return "cylinder"; }

private:
    ShapeAxis axis_;
    double radius_;
    bool open_;
};

// Radius r1 at the base growing (or shrinking) linearly to r2 at the cap.
class Cone final : public Shape {
public:
    // base != cap, radii >= 0 and not both 0 are the caller's to check; a
    // cone with equal radii is better built as a Cylinder.
    Cone(const Vec3& base, double baseRadius, const Vec3& cap, double capRadius, bool open)
        : axis_(base, cap), r1_(baseRadius), r2_(capRadius), open_(open),
          slope_((capRadius - baseRadius) / axis_.length) {}
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    Vec3 normal(const Vec3& p) const override;
    bool inside(const Vec3& p) const override;
    Bounds bounds() const override;
    const char* name() const override { return "cone"; }

private:
    double radiusAt(double h) const { return r1_ + slope_ * h; }

    ShapeAxis axis_;
    double r1_, r2_;
    bool open_;
    double slope_;  // radius change per unit of height
};

}  // namespace frameray::scene
