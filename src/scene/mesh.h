// Triangle meshes: the shared geometry behind mesh, mesh2, height_field and
// bicubic_patch (seed 003 §5.2). A TriangleMesh is immutable once built and
// held by shared_ptr, so `object { M translate ... }` copies of a declared
// mesh share its vertices and BVH; only the Object's transform differs.
//
// Triangles are grouped by their own texture (mesh triangles may carry
// one): each group has its own BVH in object space, built and traversed in
// double precision, so a group can be one primitive with its own texture
// while the inside test still counts the crossings of the whole mesh.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "scene/shapes.h"

namespace frameray::scene {

struct MeshTriangle {
    std::array<uint32_t, 3> vertex{};
    // Indices into the normals for a smooth triangle; -1 for a flat one.
    std::array<int32_t, 3> normal{-1, -1, -1};
    // The triangle's own texture (index into the mesh's texture list), or
    // -1 for the mesh object's texture.
    int32_t texture = -1;
    // Indices into the mesh's uv list for uv_mapping; -1: none given.
    std::array<int32_t, 3> uv{-1, -1, -1};
};

class TriangleMesh {
  public:
    // Degenerate triangles (corners in one line) are dropped: povray never
    // hits them either.
    // Vertex normals are made unit length unless `keepNormalLengths` (a
    // height field blends its normals as they are).
    TriangleMesh(std::vector<Vec3> vertices, std::vector<Vec3> normals,
                 std::vector<MeshTriangle> triangles, bool keepNormalLengths = false);

    // The uv coordinates the triangles' uv indices refer to (uv_vectors);
    // call before the mesh is shared.
    void setUvs(std::vector<std::array<double, 2>> uvs) { uvs_ = std::move(uvs); }
    // uv_mapping: the uv of a point on the surface, interpolated over the
    // triangle it lies on; (0, 0) on triangles without uv (measured).
    void uvAt(const Vec3& p, int group, double& u, double& v) const;

    // Hits below this object-space height are ignored (height_field's
    // water_level); call before the mesh is shared.
    void clipBelow(double y) { minY_ = y; }

    size_t triangleCount() const { return triangles_.size(); }
    // The corners of every triangle as given, in input order, degenerate
    // ones included (mesh_camera numbers the faces so).
    size_t inputTriangleCount() const { return inputFaces_.size(); }
    std::array<Vec3, 3> inputTriangle(size_t i) const {
        const auto& f = inputFaces_[i].vertex;
        return {vertices_[f[0]], vertices_[f[1]], vertices_[f[2]]};
    }
    // Its corners' unit normals (a smooth triangle); false for a flat one.
    bool inputTriangleNormals(size_t i, std::array<Vec3, 3>& n) const {
        for (size_t k = 0; k < 3; ++k) {
            const int32_t j = inputFaces_[i].normal[k];
            if (j < 0 || static_cast<size_t>(j) >= normals_.size()) return false;
            n[k] = normals_[static_cast<size_t>(j)];
        }
        return true;
    }
    // Its corners' uv (uv_vectors); false when it has none.
    bool inputTriangleUvs(size_t i, std::array<std::array<double, 2>, 3>& uv) const {
        for (size_t k = 0; k < 3; ++k) {
            const int32_t j = inputFaces_[i].uv[k];
            if (j < 0 || static_cast<size_t>(j) >= uvs_.size()) return false;
            uv[k] = uvs_[static_cast<size_t>(j)];
        }
        return true;
    }
    size_t groupCount() const { return groups_.size(); }
    // The texture index shared by the triangles of group g (-1: none).
    int32_t groupTexture(size_t g) const { return groups_[g].texture; }

    // Queries on one group, or on every group when `group` is kAllGroups.
    static constexpr int kAllGroups = -1;
    bool firstHit(const Ray& ray, double tMin, double tMax, double& t, int group) const;
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts,
                 int group) const;
    // The shading normal at a point on the surface: that of the triangle the
    // point lies on (the nearest one), interpolated for smooth triangles.
    Vec3 normal(const Vec3& p, int group) const { return normal(p, group, nullptr); }
    // With `toWorld`, the corner normals of a smooth triangle are carried
    // to world space and made unit length before they are blended (povray
    // transforms a bicubic patch's points, so blends in world space); the
    // result is then a unit world-space normal.
    Vec3 normal(const Vec3& p, int group, const Transform* toWorld) const;
    // normal() and uvAt() at once: the triangle p lies on is searched once
    // (a shading point wanting both pays one search; same results).
    Vec3 normalAndUv(const Vec3& p, int group, const Transform* toWorld, double& u,
                     double& v) const;
    Bounds bounds(int group) const;
    // Number of surface crossings along the ray beyond t = 0 (for the
    // inside test along inside_vector).
    size_t crossingCount(const Ray& ray) const;

  private:
    struct Node {
        Bounds box;
        uint32_t first = 0;  // leaf: first triangle; inner: right child (left is next)
        uint32_t count = 0;  // triangles in a leaf, 0 for an inner node
    };
    struct Group {
        int32_t texture = -1;
        std::vector<Node> nodes;
    };

    // Builds the node for triangles order[begin, end) (indices into
    // triangles_), reordering that range of `order`.
    uint32_t build(Group& g, std::vector<uint32_t>& order, uint32_t begin, uint32_t end,
                   const std::vector<Vec3>& centroids);
    // Calls visit(triangle index) for every triangle in a leaf the ray's box
    // test passes in (tMin, tMax()); tMax is re-read so a closest-hit search
    // can shrink it.
    template <typename Visit, typename Limit>
    void traverse(const Group& g, const Ray& ray, double tMin, Limit tMax, Visit visit) const;
    bool hitTriangle(uint32_t tri, const Ray& ray, double tMin, double tMax, double& t) const;
    Vec3 triangleNormal(uint32_t tri, const Vec3& p, const Transform* toWorld) const;
    // uvAt's interpolation over triangle `tri` (-1: none; u, v stay 0).
    void triangleUv(int64_t tri, const Vec3& p, double& u, double& v) const;
    // The triangle p lies on (the nearest one); -1 when there is none.
    int64_t nearestTriangle(const Vec3& p, int group) const;

    std::vector<Vec3> vertices_;
    std::vector<Vec3> normals_;
    std::vector<MeshTriangle> triangles_;   // sorted by group, then in BVH order
    std::vector<MeshTriangle> inputFaces_;  // as given, in input order
    std::vector<std::array<double, 2>> uvs_;
    std::vector<Group> groups_;
    double minY_ = -kInfinity;
};

// The shape of a mesh, or of one texture group of it. Without an inside
// vector a mesh encloses nothing (a patch); with one, a point is inside
// when a ray from it along the vector crosses the whole mesh an odd number
// of times.
class MeshShape final : public Shape {
  public:
    MeshShape(std::shared_ptr<const TriangleMesh> mesh, int group, bool hasInsideVector,
              const Vec3& insideVector)
        : mesh_(std::move(mesh)),
          group_(group),
          solid_(hasInsideVector),
          insideVector_(insideVector) {}

    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override {
        mesh_->allHits(ray, tMin, tMax, ts, group_);
    }
    bool firstHit(const Ray& ray, double tMin, double tMax, double& t) const override {
        return mesh_->firstHit(ray, tMin, tMax, t, group_);
    }
    Vec3 normal(const Vec3& p) const override { return mesh_->normal(p, group_); }
    Vec3 worldNormalUv(const Vec3& p, const Transform& toWorld, bool& hasUv, double& u,
                       double& v) const override {
        hasUv = true;
        return normalize(toWorld.normal(mesh_->normalAndUv(p, group_, nullptr, u, v)));
    }
    bool inside(const Vec3& p) const override;
    bool isPatch() const override { return !solid_; }
    Bounds bounds() const override { return mesh_->bounds(group_); }
    Bounds insideBounds() const override {
        return solid_ ? mesh_->bounds(TriangleMesh::kAllGroups) : Bounds{};
    }
    const char* name() const override { return "mesh"; }
    bool uv(const Vec3& p, double& u, double& v) const override {
        mesh_->uvAt(p, group_, u, v);
        return true;
    }

    const std::shared_ptr<const TriangleMesh>& mesh() const { return mesh_; }

  private:
    std::shared_ptr<const TriangleMesh> mesh_;
    int group_;
    bool solid_;
    Vec3 insideVector_;
};

}  // namespace frameray::scene
