#include "scene/height_field.h"

#include <algorithm>
#include <cmath>

namespace frameray::scene {

namespace {
constexpr double kHeightScale = 1.0 / 65536.0;
}

double HeightField::sample(int i, int k) const {
    i = std::clamp(i, 0, width_ - 1);
    k = std::clamp(k, 0, height_ - 1);
    return heights_[static_cast<size_t>(height_ - 1 - k) * static_cast<size_t>(width_) +
                    static_cast<size_t>(i)] *
           kHeightScale;
}

Vec3 HeightField::vertexNormal(int i, int k) const {
    // povray 3.7's smooth normals (fitted exactly to its trace() output):
    // in grid space (x, z in samples, y in 16-bit height units) the unit
    // normals of the four quadrants between the vertex and its neighbours
    // (east, north, west, south; quadrants with a neighbour off the grid
    // left out) are summed and made unit length, then stored as 16-bit
    // integers (times 32767, truncated). Carried to object space, unscaled,
    // where normal() blends them.
    auto grid = [&](int a, int b) { return Vec3(a, sample(a, b) * 65536.0, b); };
    const Vec3 p = grid(i, k);
    const int di[4] = {1, 0, -1, 0}, dk[4] = {0, 1, 0, -1};
    Vec3 sum;
    for (int q = 0; q < 4; ++q) {
        const int a1 = i + di[q], b1 = k + dk[q], a2 = i + di[(q + 1) % 4],
                  b2 = k + dk[(q + 1) % 4];
        if (a1 < 0 || a1 >= width_ || b1 < 0 || b1 >= height_ || a2 < 0 || a2 >= width_ || b2 < 0 ||
            b2 >= height_)
            continue;
        Vec3 n = cross(grid(a2, b2) - p, grid(a1, b1) - p);
        if (n.y < 0) n = -n;
        sum += normalize(n);
    }
    if (dot(sum, sum) == 0) return Vec3(0, 1, 0);
    const Vec3 unit = normalize(sum);
    const Vec3 stored(std::trunc(unit.x * 32767), std::trunc(unit.y * 32767),
                      std::trunc(unit.z * 32767));
    return Vec3(stored.x * (width_ - 1), stored.y * 65536.0, stored.z * (height_ - 1));
}

HeightField::HeightField(int width, int height, std::vector<uint16_t> heights, bool smooth,
                         double waterLevel)
    : width_(width), height_(height), heights_(std::move(heights)) {
    const double sx = 1.0 / (width_ - 1), sz = 1.0 / (height_ - 1);
    std::vector<Vec3> vertices;
    vertices.reserve(static_cast<size_t>(width_) * static_cast<size_t>(height_));
    for (int k = 0; k < height_; ++k)
        for (int i = 0; i < width_; ++i) vertices.emplace_back(i * sx, sample(i, k), k * sz);
    if (smooth) {
        smoothNormals_.reserve(vertices.size());
        for (int k = 0; k < height_; ++k)
            for (int i = 0; i < width_; ++i) smoothNormals_.push_back(vertexNormal(i, k));
    }
    std::vector<MeshTriangle> tris;
    tris.reserve(2 * static_cast<size_t>(width_ - 1) * static_cast<size_t>(height_ - 1));
    auto index = [&](int i, int k) { return static_cast<uint32_t>(k * width_ + i); };
    for (int k = 0; k + 1 < height_; ++k)
        for (int i = 0; i + 1 < width_; ++i) {
            MeshTriangle a, b;
            a.vertex = {index(i, k), index(i + 1, k), index(i, k + 1)};
            b.vertex = {index(i + 1, k), index(i + 1, k + 1), index(i, k + 1)};
            tris.push_back(a);
            tris.push_back(b);
        }
    mesh_ =
        std::make_shared<TriangleMesh>(std::move(vertices), std::vector<Vec3>{}, std::move(tris));
    if (waterLevel > 0) mesh_->clipBelow(waterLevel);
    bounds_ = mesh_->bounds(TriangleMesh::kAllGroups);
    if (!bounds_.isEmpty())
        bounds_.lo.y = std::max(bounds_.lo.y, std::min(waterLevel, bounds_.hi.y));
}

double HeightField::heightAt(double x, double z) const {
    const double fx = x * (width_ - 1), fz = z * (height_ - 1);
    const int i = std::clamp(static_cast<int>(std::floor(fx)), 0, width_ - 2);
    const int k = std::clamp(static_cast<int>(std::floor(fz)), 0, height_ - 2);
    const double u = fx - i, v = fz - k;
    // The cell's two triangles meet on the line u + v = 1.
    if (u + v <= 1)
        return sample(i, k) + (sample(i + 1, k) - sample(i, k)) * u +
               (sample(i, k + 1) - sample(i, k)) * v;
    return sample(i + 1, k + 1) + (sample(i, k + 1) - sample(i + 1, k + 1)) * (1 - u) +
           (sample(i + 1, k) - sample(i + 1, k + 1)) * (1 - v);
}

Vec3 HeightField::normal(const Vec3& p) const {
    return worldNormal(p, Transform());
}

Vec3 HeightField::worldNormal(const Vec3& p, const Transform& toWorld) const {
    if (smoothNormals_.empty())
        return normalize(toWorld.normal(mesh_->normal(p, TriangleMesh::kAllGroups)));
    // povray makes the four corner normals of the cell unit length after
    // the object's transform and blends them bilinearly, whichever of the
    // cell's triangles was hit (fitted to its trace(), scaled and not).
    const double fx = std::clamp(p.x, 0.0, 1.0) * (width_ - 1),
                 fz = std::clamp(p.z, 0.0, 1.0) * (height_ - 1);
    const int i = std::clamp(static_cast<int>(std::floor(fx)), 0, width_ - 2);
    const int k = std::clamp(static_cast<int>(std::floor(fz)), 0, height_ - 2);
    const double u = fx - i, v = fz - k;
    auto at = [&](int a, int b) {
        return normalize(toWorld.normal(smoothNormals_[static_cast<size_t>(b * width_ + a)]));
    };
    const Vec3 n = at(i, k) * ((1 - u) * (1 - v)) + at(i + 1, k) * (u * (1 - v)) +
                   at(i, k + 1) * ((1 - u) * v) + at(i + 1, k + 1) * (u * v);
    return dot(n, n) > 0 ? normalize(n)
                         : normalize(toWorld.normal(mesh_->normal(p, TriangleMesh::kAllGroups)));
}

bool HeightField::inside(const Vec3& p) const {
    if (p.x < 0 || p.x > 1 || p.z < 0 || p.z > 1 || p.y < 0) return false;
    return p.y < heightAt(p.x, p.z);
}

}  // namespace frameray::scene
