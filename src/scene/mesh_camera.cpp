#include "scene/mesh_camera.h"

#include <algorithm>
#include <cmath>

namespace frameray::scene {

bool MeshCamera::faceRay(size_t m, size_t face, Ray& ray, const std::array<double, 3>& w) const {
    const Placed& placed = meshes[m];
    if (face >= placed.mesh->inputTriangleCount()) return false;
    std::array<Vec3, 3> c = placed.mesh->inputTriangle(face);
    for (Vec3& p : c) p = placed.toWorld.point(p);
    const Vec3 n = cross(c[2] - c[0], c[1] - c[0]);
    const double len = length(n);
    if (!(len > 0)) return false;
    const Vec3 unit = n / len;
    ray.origin = c[0] * w[0] + c[1] * w[1] + c[2] * w[2] + unit * startOffset;
    ray.direction = reverse ? -unit : unit;
    return true;
}

bool MeshCamera::smoothFaceRay(size_t face, const std::array<double, 3>& w, Ray& ray) const {
    const Placed& placed = meshes.front();
    std::array<Vec3, 3> n;
    if (!placed.mesh->inputTriangleNormals(face, n)) return false;
    const std::array<Vec3, 3> c = placed.mesh->inputTriangle(face);
    // In the mesh's own space, as povray: the blend is left at its length
    // (a little under 1) for the start offset, then carried to world space.
    const Vec3 blend = n[0] * w[0] + n[1] * w[1] + n[2] * w[2];
    if (!(dot(blend, blend) > 0)) return false;
    const Vec3 start = c[0] * w[0] + c[1] * w[1] + c[2] * w[2] + blend * startOffset;
    ray.origin = placed.toWorld.point(start);
    const Vec3 dir = normalize(placed.toWorld.normal(blend));
    ray.direction = reverse ? -dir : dir;
    return true;
}

bool MeshCamera::hasUnblendableUvFace() const {
    if (meshes.empty()) return false;
    const TriangleMesh& mesh = *meshes.front().mesh;
    // povray treats corner normals as equal when their dot product is
    // within about 1e-10 of 1 (measured between 4e-11 and 4e-7); refuse a
    // wider band so that no face povray makes flat is blended here.
    constexpr double kSame = 1e-8;
    for (size_t f = 0; f < mesh.inputTriangleCount(); ++f) {
        std::array<std::array<double, 2>, 3> uv;
        if (!mesh.inputTriangleUvs(f, uv)) continue;
        std::array<Vec3, 3> n;
        if (!mesh.inputTriangleNormals(f, n)) return true;
        if (1 - dot(n[0], n[1]) < kSame && 1 - dot(n[0], n[2]) < kSame &&
            1 - dot(n[1], n[2]) < kSame)
            return true;
    }
    return false;
}

void MeshCamera::prepareUvLookup() {
    uvFaces_.clear();
    cells_.clear();
    if (meshes.empty()) return;
    const TriangleMesh& mesh = *meshes.front().mesh;
    double lo[2] = {kInfinity, kInfinity}, hi[2] = {-kInfinity, -kInfinity};
    for (size_t f = 0; f < mesh.inputTriangleCount(); ++f) {
        UvFace uvFace{f, {}};
        if (!mesh.inputTriangleUvs(f, uvFace.uv)) continue;
        for (const auto& p : uvFace.uv)
            for (int k = 0; k < 2; ++k) {
                lo[k] = std::min(lo[k], p[k]);
                hi[k] = std::max(hi[k], p[k]);
            }
        uvFaces_.push_back(uvFace);
    }
    if (uvFaces_.empty()) return;
    gridSize_ =
        std::clamp(static_cast<int>(std::sqrt(static_cast<double>(uvFaces_.size()))), 1, 1024);
    for (int k = 0; k < 2; ++k) {
        uvLo_[k] = lo[k];
        uvScale_[k] = hi[k] > lo[k] ? gridSize_ / (hi[k] - lo[k]) : 0.0;
    }
    cells_.assign(static_cast<size_t>(gridSize_) * gridSize_, {});
    auto cellOf = [&](double value, int k) {
        return std::clamp(static_cast<int>((value - uvLo_[k]) * uvScale_[k]), 0, gridSize_ - 1);
    };
    for (size_t i = 0; i < uvFaces_.size(); ++i) {
        const auto& uv = uvFaces_[i].uv;
        int c0[2], c1[2];
        for (int k = 0; k < 2; ++k) {
            c0[k] = cellOf(std::min({uv[0][k], uv[1][k], uv[2][k]}), k);
            c1[k] = cellOf(std::max({uv[0][k], uv[1][k], uv[2][k]}), k);
        }
        for (int cy = c0[1]; cy <= c1[1]; ++cy)
            for (int cx = c0[0]; cx <= c1[0]; ++cx)
                cells_[static_cast<size_t>(cy) * gridSize_ + cx].push_back(
                    static_cast<uint32_t>(i));
    }
}

bool MeshCamera::uvRay(double u, double v, Ray& ray) const {
    if (cells_.empty()) return false;
    const double p[2] = {u, v};
    int cell[2];
    for (int k = 0; k < 2; ++k) {
        const double g = (p[k] - uvLo_[k]) * uvScale_[k];
        if (g < -1e-9 || g > gridSize_ + 1e-9) return false;
        cell[k] = std::clamp(static_cast<int>(g), 0, gridSize_ - 1);
    }
    constexpr double kEdge = 1e-9;  // points on a shared edge belong to the first face
    for (const uint32_t i : cells_[static_cast<size_t>(cell[1]) * gridSize_ + cell[0]]) {
        const auto& t = uvFaces_[i].uv;
        const double d =
            (t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[2][0] - t[0][0]) * (t[1][1] - t[0][1]);
        if (d == 0) continue;
        const double w1 =
            ((u - t[0][0]) * (t[2][1] - t[0][1]) - (t[2][0] - t[0][0]) * (v - t[0][1])) / d;
        const double w2 =
            ((t[1][0] - t[0][0]) * (v - t[0][1]) - (u - t[0][0]) * (t[1][1] - t[0][1])) / d;
        const double w0 = 1 - w1 - w2;
        if (w0 < -kEdge || w1 < -kEdge || w2 < -kEdge) continue;
        if (smooth && smoothFaceRay(uvFaces_[i].face, {w0, w1, w2}, ray)) return true;
        return faceRay(0, uvFaces_[i].face, ray, {w0, w1, w2});
    }
    return false;
}

void MeshCamera::pixelRays(int x, int y, int width, int height, std::vector<Ray>& rays) const {
    if (x < 0 || y < 0 || meshes.empty()) return;
    Ray ray;
    if (distribution == 3) {
        const double u = (x < width - 1 ? x : x - 0.5) / width;
        const double v = 1 - (y > 0 ? y : 0.5) / height;
        if (uvRay(u, v, ray)) rays.push_back(ray);
        return;
    }
    const size_t index = static_cast<size_t>(std::max(y - 1, 0)) * static_cast<size_t>(width) +
                         static_cast<size_t>(x);
    if (distribution == 2) {
        const size_t n = meshes.size();
        const size_t stripWidth = static_cast<size_t>(width) / n;
        if (stripWidth == 0) return;
        const double strip = static_cast<double>(width) / static_cast<double>(n);
        const size_t m = std::min(static_cast<size_t>(x / strip), n - 1);
        const size_t face =
            static_cast<size_t>(std::max(y - 1, 0)) * stripWidth + static_cast<size_t>(x);
        if (faceRay(m, face, ray)) rays.push_back(ray);
        return;
    }
    if (distribution == 0) {
        const size_t count =
            std::min(meshes.size(), static_cast<size_t>(std::max(raysPerPixel, 1)));
        for (size_t m = 0; m < count; ++m)
            if (faceRay(m, index, ray)) rays.push_back(ray);
        return;
    }
    // Distribution 1: the meshes' faces as one list.
    size_t face = index;
    for (size_t m = 0; m < meshes.size(); ++m) {
        const size_t n = meshes[m].mesh->inputTriangleCount();
        if (face < n) {
            if (faceRay(m, face, ray)) rays.push_back(ray);
            return;
        }
        face -= n;
    }
}

}  // namespace frameray::scene
