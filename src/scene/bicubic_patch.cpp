#include "scene/bicubic_patch.h"

#include <cmath>
#include <functional>
#include <utility>

namespace frameray::scene {

namespace {

// Bernstein polynomials of degree 3 and their derivatives.
void bernstein(double t, double b[4], double d[4]) {
    const double s = 1 - t;
    b[0] = s * s * s;
    b[1] = 3 * t * s * s;
    b[2] = 3 * t * t * s;
    b[3] = t * t * t;
    d[0] = -3 * s * s;
    d[1] = 3 * s * s - 6 * t * s;
    d[2] = 6 * t * s - 3 * t * t;
    d[3] = 3 * t * t;
}

}  // namespace

Vec3 BicubicPatch::point(double u, double v) const {
    double bu[4], du[4], bv[4], dv[4];
    bernstein(u, bu, du);
    bernstein(v, bv, dv);
    Vec3 p;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) p += points_[static_cast<size_t>(4 * r + c)] * (bv[r] * bu[c]);
    return p;
}

Vec3 BicubicPatch::surfaceNormal(double u, double v) const {
    double bu[4], du[4], bv[4], dv[4];
    bernstein(u, bu, du);
    bernstein(v, bv, dv);
    Vec3 pu, pv;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            pu += points_[static_cast<size_t>(4 * r + c)] * (bv[r] * du[c]);
            pv += points_[static_cast<size_t>(4 * r + c)] * (dv[r] * bu[c]);
        }
    return cross(pu, pv);
}

BicubicPatch::BicubicPatch(const std::array<Vec3, 16>& points, int uSteps, int vSteps,
                           double flatness)
    : points_(points) {
    std::vector<Vec3> vertices, normals;
    std::vector<MeshTriangle> tris;
    // A corner's normal; where the derivatives vanish (a collapsed edge)
    // the normal a little inside the patch.
    auto cornerNormal = [&](double u, double v) {
        Vec3 n = surfaceNormal(u, v);
        if (dot(n, n) == 0)
            n = surfaceNormal(u + (u < 0.5 ? 1e-6 : -1e-6), v + (v < 0.5 ? 1e-6 : -1e-6));
        return n;
    };
    auto addVertex = [&](double u, double v) {
        vertices.push_back(point(u, v));
        normals.push_back(cornerNormal(u, v));
        return static_cast<uint32_t>(vertices.size() - 1);
    };
    auto addQuad = [&](uint32_t p00, uint32_t p10, uint32_t p01, uint32_t p11) {
        // Cut along (u0, v0)-(u1, v1).
        MeshTriangle a, b;
        a.vertex = {p00, p10, p11};
        b.vertex = {p00, p11, p01};
        for (size_t k = 0; k < 3; ++k) {
            a.normal[k] = static_cast<int32_t>(a.vertex[k]);
            b.normal[k] = static_cast<int32_t>(b.vertex[k]);
        }
        tris.push_back(a);
        tris.push_back(b);
    };
    // povray's u_steps splits along the rows of control points (the v
    // direction here), v_steps along the columns (measured with trace()).
    std::swap(uSteps, vSteps);
    uSteps = std::max(uSteps, 0);
    vSteps = std::max(vSteps, 0);
    if (flatness <= 0) {
        // The full grid, with shared corners.
        const int nu = 1 << uSteps, nv = 1 << vSteps;
        for (int j = 0; j <= nv; ++j)
            for (int i = 0; i <= nu; ++i)
                addVertex(static_cast<double>(i) / nu, static_cast<double>(j) / nv);
        auto at = [&](int i, int j) { return static_cast<uint32_t>(j * (nu + 1) + i); };
        for (int j = 0; j < nv; ++j)
            for (int i = 0; i < nu; ++i)
                addQuad(at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1));
    } else {
        // Split while a sub-patch strays from the plane of its corners by
        // more than `flatness` (measured on a 4 x 4 sample of it).
        std::function<void(double, double, double, double, int, int)> split =
            [&](double u0, double u1, double v0, double v1, int du, int dv) {
                const bool canU = du < uSteps, canV = dv < vSteps;
                bool flat = true;
                if (canU || canV) {
                    const Vec3 c00 = point(u0, v0), c11 = point(u1, v1), c10 = point(u1, v0),
                               c01 = point(u0, v1);
                    Vec3 n = cross(c11 - c00, c01 - c10);
                    const double len = length(n);
                    double worst = 0;
                    for (int j = 0; j < 4 && flat; ++j)
                        for (int i = 0; i < 4; ++i) {
                            const Vec3 p =
                                point(u0 + (u1 - u0) * i / 3.0, v0 + (v1 - v0) * j / 3.0);
                            const double d =
                                len > 0 ? std::fabs(dot(p - (c00 + c11 + c10 + c01) / 4.0, n)) / len
                                        : length(p - c00);
                            worst = std::max(worst, d);
                        }
                    flat = worst <= flatness;
                }
                if (flat || (!canU && !canV)) {
                    addQuad(addVertex(u0, v0), addVertex(u1, v0), addVertex(u0, v1),
                            addVertex(u1, v1));
                    return;
                }
                const double um = canU ? (u0 + u1) / 2 : u1, vm = canV ? (v0 + v1) / 2 : v1;
                const int ndu = canU ? du + 1 : du, ndv = canV ? dv + 1 : dv;
                split(u0, um, v0, vm, ndu, ndv);
                if (canU) split(um, u1, v0, vm, ndu, ndv);
                if (canV) split(u0, um, vm, v1, ndu, ndv);
                if (canU && canV) split(um, u1, vm, v1, ndu, ndv);
            };
        split(0, 1, 0, 1, 0, 0);
    }
    mesh_ = std::make_shared<const TriangleMesh>(std::move(vertices), std::move(normals),
                                                 std::move(tris));
}

}  // namespace frameray::scene
