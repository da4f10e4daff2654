// Flat shapes: discs, triangles and smooth triangles (seed 003 §5.2).
#pragma once

#include "scene/shapes.h"

namespace frameray::scene {

// disc { center, normal, radius [, hole_radius] }: a flat ring. Its inside
// test is the half-space behind the normal, whatever the radius (povray:
// difference { sphere disc } keeps the whole hemisphere in front of the
// disc's plane even when the disc is smaller than the sphere). Yet
// intersection { sphere disc } shows the sphere only along rays through the
// disc's thin bounding box (see Shape::insideReachesPastBounds).
class Disc final : public Shape {
public:
    // normal must not be zero (the caller checks).
    Disc(const Vec3& center, const Vec3& normal, double radius, double holeRadius);
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    Vec3 normal(const Vec3&) const override { return normal_; }
    bool inside(const Vec3& p) const override { return dot(p - center_, normal_) < 0; }
    Bounds bounds() const override;
    Bounds insideBounds() const override { return Bounds::infinite(); }
    bool insideReachesPastBounds() const override { return true; }
    const char* name() const override { return "disc"; }

private:
    static constexpr double kThickness = 0.001;  // of the bounding box, each side
    Vec3 center_, normal_;  // normal_ unit length
    double radius2_, hole2_;
};

// triangle { a, b, c }: a patch, enclosing nothing.
class Triangle : public Shape {
public:
    Triangle(const Vec3& a, const Vec3& b, const Vec3& c);
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    bool firstHit(const Ray& ray, double tMin, double tMax, double& t) const override;
    Vec3 normal(const Vec3&) const override { return normalize(cross(b_ - a_, c_ - a_)); }
    bool inside(const Vec3&) const override { return false; }
    bool isPatch() const override { return true; }
    Bounds bounds() const override;
    Bounds insideBounds() const override { return {}; }
    const char* name() const override { return "triangle"; }
    // Whether the corners lie in one line: povray warns and the triangle
    // is never hit.
    bool isDegenerate() const { return degenerate_; }

protected:
    // Barycentric weights of the corners b and c at a point in the plane.
    void weights(const Vec3& p, double& wb, double& wc) const;

    Vec3 a_, b_, c_;
    bool degenerate_;
};

// smooth_triangle { a, na, b, nb, c, nc }: a triangle whose shading normal
// blends the corner normals by the hit point's barycentric weights.
class SmoothTriangle final : public Triangle {
public:
    SmoothTriangle(const Vec3& a, const Vec3& na, const Vec3& b, const Vec3& nb, const Vec3& c, const Vec3& nc);
    Vec3 normal(const Vec3& p) const override;
    const char* name() const override { return "smooth_triangle"; }

private:
    Vec3 na_, nb_, nc_;  // unit length
};

}  // namespace frameray::scene
