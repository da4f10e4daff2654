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
//     black;
//   - distribution 3: pixel (x, y) is the uv point (x / W, 1 - y / H),
//     except u = (W - 1.5) / W in the last column and v = 1 - 0.5 / H in
//     the top row; the ray starts at the point of the (first) mesh whose
//     uv_vectors hold it, along that face's normal as above. A uv point on
//     no face stays black;
//   - `smooth` (distribution 3): the ray runs along the face's corner
//     normals blended by the point's barycentric weights; `location` z
//     moves the start along that blended, not yet unit, normal in the
//     mesh's own space (flat faces: see hasUnblendableUvFace);
//   - distribution 2: side-by-side cameras. Mesh k of n covers the columns
//     [k W / n, (k + 1) W / n); its face is row * (W / n) + x with the
//     image's x, not the column inside the strip (as povray 3.7: every
//     strip but the first starts k rows down its mesh). A pixel past a
//     mesh's last face stays black.
#pragma once

#include <array>
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
    bool smooth = false;     // distribution 3: blend smooth faces' normals

    // Distribution 3: indexes the first mesh's faces by their uv; call
    // once the meshes are in.
    void prepareUvLookup();

    // `smooth` over a face povray blends no normals for: a flat one, or a
    // smooth one whose corner normals (nearly) agree, which povray makes
    // flat. povray then gives rays along no normal of the face (+x or +y
    // of the mesh, measured), so frameray refuses such a mesh. True when
    // the first mesh has a uv-mapped face of either kind.
    bool hasUnblendableUvFace() const;

    // The rays of pixel (x, y) of a width x height image, appended to `rays`.
    void pixelRays(int x, int y, int width, int height, std::vector<Ray>& rays) const;

  private:
    // Face `face` of mesh `m`'s ray, from the point with barycentric
    // weights `w` (the centroid by default); false past its last face or on
    // a degenerate one.
    bool faceRay(size_t m, size_t face, Ray& ray,
                 const std::array<double, 3>& w = {1.0 / 3, 1.0 / 3, 1.0 / 3}) const;
    // `smooth`: the ray from the point with weights `w` of smooth face
    // `face` of the first mesh, along its blended corner normals; false on
    // a flat face.
    bool smoothFaceRay(size_t face, const std::array<double, 3>& w, Ray& ray) const;
    // Distribution 3: the ray from uv point (u, v), if a face holds it.
    bool uvRay(double u, double v, Ray& ray) const;

    struct UvFace {
        size_t face;
        std::array<std::array<double, 2>, 3> uv;
    };
    std::vector<UvFace> uvFaces_;
    // A uniform grid over the uv bounds: the faces overlapping each cell.
    int gridSize_ = 0;
    double uvLo_[2] = {0, 0}, uvScale_[2] = {1, 1};
    std::vector<std::vector<uint32_t>> cells_;
};

}  // namespace frameray::scene
