// bicubic_patch (seed 003 §5.2.2.2): a Bezier patch of 16 control points,
// rendered as POV-Ray 3.7 renders it: subdivided into 2^u_steps x
// 2^v_steps sub-patches (fewer where `flatness` finds a sub-patch flat
// enough), each drawn as two smooth triangles between its corners, cut
// along the diagonal from (u0, v0) to (u1, v1); corner points and normals
// lie on the exact surface (measured with povray's trace()). Types 0 and
// 1 differ only in what povray keeps in memory, not in the image. A patch
// encloses nothing.
//
// With flatness > 0 a sub-patch stops splitting once its control net lies
// within `flatness` of the plane through three of its corners, measured
// where the patch is placed (povray moves the control points with every
// transform and subdivides again), so each transform builds the patch
// anew (placedBy).
#pragma once

#include <array>
#include <memory>

#include "scene/mesh.h"

namespace frameray::scene {

class BicubicPatch final : public Shape {
  public:
    // uv_vectors: the (u, v) that uv_mapping gives the corners (u, v) =
    // (0, 0), (1, 0), (1, 1), (0, 1), blended bilinearly in between.
    using UvCorners = std::array<std::array<double, 2>, 4>;
    static constexpr UvCorners kUnitUvCorners = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};

    // points[4 * row + column]: the row runs along v, the column along u.
    // `placement` only decides where flatness measures distances.
    BicubicPatch(const std::array<Vec3, 16>& points, int uSteps, int vSteps, double flatness,
                 const Transform& placement = Transform(),
                 const UvCorners& uvCorners = kUnitUvCorners);
    std::shared_ptr<const Shape> placedBy(const Transform& toWorld) const override;

    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override {
        mesh_->allHits(ray, tMin, tMax, ts, TriangleMesh::kAllGroups);
    }
    bool firstHit(const Ray& ray, double tMin, double tMax, double& t) const override {
        return mesh_->firstHit(ray, tMin, tMax, t, TriangleMesh::kAllGroups);
    }
    Vec3 normal(const Vec3& p) const override { return mesh_->normal(p, TriangleMesh::kAllGroups); }
    // povray moves the control points themselves, so a sub-patch's corner
    // normals are blended in world space.
    Vec3 worldNormal(const Vec3& p, const Transform& toWorld) const override {
        return mesh_->normal(p, TriangleMesh::kAllGroups, &toWorld);
    }
    Vec3 worldNormalUv(const Vec3& p, const Transform& toWorld, bool& hasUv, double& u,
                       double& v) const override {
        hasUv = true;
        return mesh_->normalAndUv(p, TriangleMesh::kAllGroups, &toWorld, u, v);
    }
    bool inside(const Vec3&) const override { return false; }
    bool isPatch() const override { return true; }
    Bounds bounds() const override { return mesh_->bounds(TriangleMesh::kAllGroups); }
    // uv_mapping: the patch parameters (u, v) of the point.
    bool uv(const Vec3& p, double& u, double& v) const override {
        mesh_->uvAt(p, TriangleMesh::kAllGroups, u, v);
        return true;
    }
    Bounds insideBounds() const override { return {}; }
    const char* name() const override { return "bicubic_patch"; }

    // The surface point and (unnormalised) normal at (u, v).
    Vec3 point(double u, double v) const;
    Vec3 surfaceNormal(double u, double v) const;
    size_t triangleCount() const { return mesh_->triangleCount(); }

  private:
    // How far the control net of the sub-patch [u0, u1] x [v0, v1] strays
    // from the plane through three of its corners.
    double subPatchFlatness(double u0, double u1, double v0, double v1) const;

    std::array<Vec3, 16> points_;
    int uSteps_, vSteps_;
    double flatness_;
    Transform placement_;
    UvCorners uvCorners_;
    std::shared_ptr<const TriangleMesh> mesh_;
};

}  // namespace frameray::scene
