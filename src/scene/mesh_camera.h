// mesh_camera { RAYS DISTRIBUTION mesh { ... } ... } (POV-Ray 3.7): every
// primary ray comes from a face of a mesh, whatever the image plane. As
// povray 3.7 renders it (measured with a surface that shows the hit point):
//   - a face's ray starts at its centroid and runs along its unit normal
//     cross(c - a, b - a) of its corners a, b, c as written; the camera's
//     `location` z moves the start along that normal, a negative
//     `direction` z reverses the ray; the camera's other vectors and its
//     transformations change nothing;
//   - pixel (x, y) of a W-wide image takes face (max(y - 1, 0)) * W + x
//     (the top two rows share the first row of faces);
//   - distribution 0: that face of each of the first RAYS meshes, the
//     colours averaged; distribution 1: the meshes' faces counted one
//     after the other as a single list. A pixel past the last face stays
//     black.
// Distributions 2 and 3 (face chosen by mesh interleaving and by uv) and
// `smooth` are not reproduced.
#pragma once

#include <memory>
#include <vector>

#include "scene/mesh.h"
#include "util/matrix.h"

namespace frameray::scene {

struct MeshCamera {
    int raysPerPixel = 1;
    int distribution = 0;
    struct Placed {
        std::shared_ptr<const TriangleMesh> mesh;
        Transform toWorld;
    };
    std::vector<Placed> meshes;
    double startOffset = 0;  // the camera's location z
    bool reverse = false;    // the camera's direction z < 0

    // The rays of pixel (x, y) of a `width`-wide image, appended to `rays`.
    void pixelRays(int x, int y, int width, std::vector<Ray>& rays) const;

  private:
    // Face `face` of mesh `m`'s ray; false past its last face or on a
    // degenerate one.
    bool faceRay(size_t m, size_t face, Ray& ray) const;
};

}  // namespace frameray::scene
