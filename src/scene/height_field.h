// height_field (seed 003 §5.2.1.7): a grid of heights over the unit square
// x, z in [0, 1], y in [0, 1), as POV-Ray 3.7 builds it:
//   - sample (i, j) of a W x H grid (row j = 0 is the image's top row)
//     sits at x = i / (W - 1), z = 1 - j / (H - 1);
//   - heights are 16-bit values h, at y = h / 65536 (an 8-bit grey value
//     v counts as v * 257, a colour pixel as red * 256 + green);
//   - each cell is cut into two triangles along the diagonal from
//     (x + 1, z) to (x, z + 1) (measured with povray's trace());
//   - water_level L ignores every hit below y = L.
// The surface is the triangles only; a point is inside when it lies over
// the square, above y = 0 and below the surface.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "scene/mesh.h"

namespace frameray::scene {

class HeightField final : public Shape {
  public:
    // `heights` holds width * height samples, row-major from the top row.
    HeightField(int width, int height, std::vector<uint16_t> heights, bool smooth,
                double waterLevel);

    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override {
        mesh_->allHits(ray, tMin, tMax, ts, TriangleMesh::kAllGroups);
    }
    bool firstHit(const Ray& ray, double tMin, double tMax, double& t) const override {
        return mesh_->firstHit(ray, tMin, tMax, t, TriangleMesh::kAllGroups);
    }
    Vec3 normal(const Vec3& p) const override;
    Vec3 worldNormal(const Vec3& p, const Transform& toWorld) const override;
    bool inside(const Vec3& p) const override;
    Bounds bounds() const override { return bounds_; }
    const char* name() const override { return "height_field"; }

    // The surface height over (x, z) in the unit square (tests, inside).
    double heightAt(double x, double z) const;
    // The height of grid sample (i, k): column i, k-th row from z = 0.
    double sample(int i, int k) const;

  private:
    // The smooth normal of grid sample (i, k), in object space, not unit
    // length.
    Vec3 vertexNormal(int i, int k) const;

    int width_, height_;
    std::vector<uint16_t> heights_;
    std::vector<Vec3>
        smoothNormals_;  // object space, per sample (k * width + i); empty unless smooth
    std::shared_ptr<TriangleMesh> mesh_;
    Bounds bounds_;
};

}  // namespace frameray::scene
