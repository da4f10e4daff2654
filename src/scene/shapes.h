// Geometric primitives in object space, in double precision. Each shape
// answers the first hit along a ray, every crossing along a ray (for CSG),
// an inside test, the surface normal at a point, and its bounds. Shapes
// know nothing of transforms: Object applies those.
#pragma once

#include <memory>
#include <vector>

#include "scene/ray.h"
#include "util/matrix.h"

namespace frameray::scene {

class Shape {
  public:
    virtual ~Shape() = default;

    // All ray parameters t in (tMin, tMax) where the ray crosses the surface,
    // appended to `ts` in increasing order.
    virtual void allHits(const Ray& ray, double tMin, double tMax,
                         std::vector<double>& ts) const = 0;
    // First crossing in (tMin, tMax); the default uses allHits.
    virtual bool firstHit(const Ray& ray, double tMin, double tMax, double& t) const;
    // Outward unit normal at a point on the surface.
    virtual Vec3 normal(const Vec3& p) const = 0;
    // povray's depth tolerance of this kind of shape, in world units along
    // a unit ray: crossings nearer the ray's origin are not seen (0: only
    // the tracer's common minimum applies). See scene/hit_tolerance.h.
    virtual double depthTolerance() const { return 0; }
    // The unit world-space normal at object-space point p of this shape
    // placed by `toWorld`. Shapes that blend normals after the transform
    // (povray's smooth height fields) override it.
    virtual Vec3 worldNormal(const Vec3& p, const Transform& toWorld) const {
        return normalize(toWorld.normal(normal(p)));
    }
    // POV-Ray's inside test, used by CSG and clipped_by. How a point ON the
    // surface counts differs per shape, as in povray 3.7 (measured with
    // coincident CSG surfaces): boxes include their faces, planes a 1e-10
    // margin, cylinders and cones exclude a 1e-10 margin, the rest compare
    // exactly. This decides which of two coincident faces survives.
    virtual bool inside(const Vec3& p) const = 0;
    // Patch shapes (triangles) enclose nothing: their inside test is false
    // whether or not they are inverted (povray: "Patch objects not allowed
    // in intersection", and difference { sphere triangle } keeps no sphere).
    virtual bool isPatch() const { return false; }
    // Whether povray warns "Patch objects not allowed in intersection" for
    // it (not for a parametric, which encloses nothing all the same).
    virtual bool warnsAsPatch() const { return isPatch(); }
    // Object-space bounds of the surface; Bounds::infinite() for unbounded
    // shapes.
    virtual Bounds bounds() const = 0;
    // Object-space bounds of the region where inside() can be true; the
    // surface bounds unless the inside reaches further (a disc's inside is
    // a half-space) or is empty (patches).
    virtual Bounds insideBounds() const { return bounds(); }
    // Object-space bounds of where inside() can be true within `box`
    // (which may be infinite along some axes): what an intersection learns
    // about an unbounded operand from the others (an infinite cylinder cut
    // by two planes). Conservative; tighter than insideBounds() ∩ box only
    // where a shape knows better.
    virtual Bounds insideBoundsWithin(const Bounds& box) const {
        return insideBounds().intersected(box);
    }
    // Whether inside() holds beyond bounds() (a disc's half-space). povray
    // skips a CSG intersection along rays that miss the common part of its
    // operands' bounding boxes, which only shows with such shapes.
    virtual bool insideReachesPastBounds() const { return false; }
    virtual const char* name() const = 0;
    // uv_mapping (povray 3.7, measured): the surface coordinates (u, v) of
    // object-space point p on the surface. False for shapes without their
    // own, which povray maps by the world x and y of the point instead.
    virtual bool uv(const Vec3& /*p*/, double& /*u*/, double& /*v*/) const { return false; }
    // worldNormal() and uv() of one point at once (`hasUv`: uv()'s result),
    // for shapes that share work between the two (meshes find the point's
    // triangle once). Results equal the separate calls'.
    virtual Vec3 worldNormalUv(const Vec3& p, const Transform& toWorld, bool& hasUv, double& u,
                               double& v) const {
        hasUv = uv(p, u, v);
        return worldNormal(p, toWorld);
    }
    // A shape whose geometry depends on where it is placed (a bicubic
    // patch with flatness subdivides by world-space distances) returns
    // its rebuilt self for the object-to-world transform `toWorld`; the
    // rest return null.
    virtual std::shared_ptr<const Shape> placedBy(const Transform& /*toWorld*/) const {
        return nullptr;
    }
};

class Sphere final : public Shape {
  public:
    Sphere(const Vec3& center, double radius) : center_(center), radius_(radius) {}
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    bool firstHit(const Ray& ray, double tMin, double tMax, double& t) const override;
    Vec3 normal(const Vec3& p) const override { return (p - center_) / radius_; }
    bool inside(const Vec3& p) const override;
    Bounds bounds() const override;
    const char* name() const override { return "sphere"; }
    bool uv(const Vec3& p, double& u, double& v) const override;

  private:
    Vec3 center_;
    double radius_;
};

// The half-space below `normal . p = distance`; its surface is the plane.
class Plane final : public Shape {
  public:
    Plane(const Vec3& normal, double distance);
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    bool firstHit(const Ray& ray, double tMin, double tMax, double& t) const override;
    Vec3 normal(const Vec3&) const override { return normal_; }
    bool inside(const Vec3& p) const override {
        return dot(p, normal_) - distance_ < kInsideMargin;
    }
    Bounds bounds() const override { return Bounds::infinite(); }
    // A half-space along an axis is bounded on one side (clipped_by
    // { plane { y, 0 } } bounds the clipped object from above).
    Bounds insideBounds() const override;
    const char* name() const override { return "plane"; }

  private:
    // povray keeps points up to 1e-10 beyond the plane inside.
    static constexpr double kInsideMargin = 1e-10;
    Vec3 normal_;      // unit length
    double distance_;  // along normal_, scaled with it
};

class Box final : public Shape {
  public:
    Box(const Vec3& corner1, const Vec3& corner2)
        : lo_(vmin(corner1, corner2)), hi_(vmax(corner1, corner2)) {}
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    bool firstHit(const Ray& ray, double tMin, double tMax, double& t) const override;
    Vec3 normal(const Vec3& p) const override;
    bool inside(const Vec3& p) const override;
    Bounds bounds() const override { return {lo_, hi_}; }
    const char* name() const override { return "box"; }
    bool uv(const Vec3& p, double& u, double& v) const override;

  private:
    // Where the ray enters and leaves the slabs; false when it misses.
    bool slabs(const Ray& ray, double& tNear, double& tFar) const;

    Vec3 lo_, hi_;
};

}  // namespace frameray::scene
