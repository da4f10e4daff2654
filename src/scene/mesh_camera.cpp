#include "scene/mesh_camera.h"

#include <algorithm>

namespace frameray::scene {

bool MeshCamera::faceRay(size_t m, size_t face, Ray& ray) const {
    const Placed& placed = meshes[m];
    if (face >= placed.mesh->inputTriangleCount()) return false;
    std::array<Vec3, 3> c = placed.mesh->inputTriangle(face);
    for (Vec3& p : c) p = placed.toWorld.point(p);
    const Vec3 n = cross(c[2] - c[0], c[1] - c[0]);
    const double len = length(n);
    if (!(len > 0)) return false;
    const Vec3 unit = n / len;
    ray.origin = (c[0] + c[1] + c[2]) / 3.0 + unit * startOffset;
    ray.direction = reverse ? -unit : unit;
    return true;
}

void MeshCamera::pixelRays(int x, int y, int width, std::vector<Ray>& rays) const {
    if (x < 0 || y < 0 || meshes.empty()) return;
    const size_t index = static_cast<size_t>(std::max(y - 1, 0)) * static_cast<size_t>(width) +
                         static_cast<size_t>(x);
    Ray ray;
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
