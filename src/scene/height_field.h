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
// the square and below the surface (however far below: povray 3.7 puts no
// floor under it, measured with CSG).
//
// No triangles are stored: a min/max quadtree over the grid's cells (like a
// BVH whose boxes come from the heights) leads a ray to the cells it may
// cross, whose two triangles are then built from the samples. A
// 1024 x 1024 field costs a few megabytes, not a mesh of two million
// triangles.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "scene/shapes.h"

namespace frameray::scene {

class HeightField final : public Shape {
  public:
    // `heights` holds width * height samples, row-major from the top row.
    HeightField(int width, int height, std::vector<uint16_t> heights, bool smooth,
                double waterLevel);

    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    bool firstHit(const Ray& ray, double tMin, double tMax, double& t) const override;
    Vec3 normal(const Vec3& p) const override;
    Vec3 worldNormal(const Vec3& p, const Transform& toWorld) const override;
    bool inside(const Vec3& p) const override;
    Bounds bounds() const override { return bounds_; }
    Bounds insideBounds() const override { return {{0, -kInfinity, 0}, {1, bounds_.hi.y, 1}}; }
    const char* name() const override { return "height_field"; }

    // The surface height over (x, z) in the unit square (tests, inside).
    double heightAt(double x, double z) const;
    // The height of grid sample (i, k): column i, k-th row from z = 0.
    double sample(int i, int k) const;

  private:
    // The smooth normal of grid sample (i, k), in object space, not unit
    // length.
    Vec3 vertexNormal(int i, int k) const;
    // Height units (0..65535) of sample (i, k), unchecked.
    uint16_t raw(int i, int k) const {
        return heights_[static_cast<size_t>(height_ - 1 - k) * static_cast<size_t>(width_) +
                        static_cast<size_t>(i)];
    }
    // Object-space corner of the grid (i, k).
    Vec3 corner(int i, int k) const { return {i * sx_, raw(i, k) / 65536.0, k * sz_}; }
    // The two triangles of cell (i, k) (0 or 1): which one p lies over.
    static int triangleOf(double u, double v) { return u + v <= 1 ? 0 : 1; }
    bool hitCell(int i, int k, const Ray& ray, double tMin, double tMax, double hits[2],
                 int& count) const;
    // Visits the cells whose quadtree boxes the ray passes through in
    // (tMin, tMax()), nearer boxes first; visit returns false to stop.
    template <typename Visit, typename Limit>
    void traverse(const Ray& ray, double tMin, Limit tMax, Visit visit) const;
    Vec3 flatNormal(const Vec3& p) const;

    // Quadtree level l has cells of 2^l x 2^l grid cells, each with the
    // lowest and highest height (in height units) beneath it.
    struct Level {
        int nx, nz;
        std::vector<std::array<uint16_t, 2>> range;
    };

    int width_, height_;
    std::vector<uint16_t> heights_;
    std::vector<Vec3>
        smoothNormals_;          // object space, per sample (k * width + i); empty unless smooth
    std::vector<Level> levels_;  // levels_[0]: the grid cells
    double sx_, sz_;             // grid spacing in x and z
    double waterLevel_;
    Bounds bounds_;
};

}  // namespace frameray::scene
