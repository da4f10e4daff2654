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

// A cubic Bezier's blossom f(t1, t2, t3): f(a, a, a) is the point at a,
// and the curve over [a, b] has control points f(a,a,a), f(a,a,b),
// f(a,b,b), f(b,b,b).
Vec3 blossom(const Vec3 p[4], double t1, double t2, double t3) {
    Vec3 q[3], r[2];
    for (int i = 0; i < 3; ++i) q[i] = p[i] * (1 - t1) + p[i + 1] * t1;
    for (int i = 0; i < 2; ++i) r[i] = q[i] * (1 - t2) + q[i + 1] * t2;
    return r[0] * (1 - t3) + r[1] * t3;
}

void restrictCurve(const Vec3 p[4], double a, double b, Vec3 out[4]) {
    out[0] = blossom(p, a, a, a);
    out[1] = blossom(p, a, a, b);
    out[2] = blossom(p, a, b, b);
    out[3] = blossom(p, b, b, b);
}

}  // namespace

double BicubicPatch::subPatchFlatness(double u0, double u1, double v0, double v1) const {
    // The sub-patch's own control net.
    Vec3 rows[4][4], net[4][4];
    for (int r = 0; r < 4; ++r) {
        const Vec3 row[4] = {
            points_[static_cast<size_t>(4 * r)], points_[static_cast<size_t>(4 * r + 1)],
            points_[static_cast<size_t>(4 * r + 2)], points_[static_cast<size_t>(4 * r + 3)]};
        restrictCurve(row, u0, u1, rows[r]);
    }
    for (int c = 0; c < 4; ++c) {
        const Vec3 column[4] = {rows[0][c], rows[1][c], rows[2][c], rows[3][c]};
        Vec3 out[4];
        restrictCurve(column, v0, v1, out);
        for (int r = 0; r < 4; ++r) net[r][c] = out[r];
    }
    for (auto& row : net)
        for (Vec3& q : row) q = placement_.point(q);
    auto planeDistance = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
        const Vec3 n = cross(b - a, c - a);
        const double len = length(n);
        double worst = 0;
        for (const auto& row : net)
            for (const Vec3& q : row)
                worst = std::max(worst, len > 0 ? std::fabs(dot(q - a, n)) / len : length(q - a));
        return worst;
    };
    return planeDistance(net[0][0], net[0][3], net[3][0]);
}

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

std::shared_ptr<const Shape> BicubicPatch::placedBy(const Transform& toWorld) const {
    if (flatness_ <= 0) return nullptr;  // the same triangles wherever it is
    return std::make_shared<BicubicPatch>(points_, uSteps_, vSteps_, flatness_, toWorld,
                                          uvCorners_);
}

BicubicPatch::BicubicPatch(const std::array<Vec3, 16>& points, int uSteps, int vSteps,
                           double flatness, const Transform& placement, const UvCorners& uvCorners)
    : points_(points),
      uSteps_(uSteps),
      vSteps_(vSteps),
      flatness_(flatness),
      placement_(placement),
      uvCorners_(uvCorners) {
    std::vector<Vec3> vertices, normals;
    std::vector<std::array<double, 2>> uvs;
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
        const UvCorners& c = uvCorners_;
        const double w00 = (1 - u) * (1 - v), w10 = u * (1 - v), w11 = u * v, w01 = (1 - u) * v;
        uvs.push_back({w00 * c[0][0] + w10 * c[1][0] + w11 * c[2][0] + w01 * c[3][0],
                       w00 * c[0][1] + w10 * c[1][1] + w11 * c[2][1] + w01 * c[3][1]});
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
            a.uv[k] = static_cast<int32_t>(a.vertex[k]);
            b.uv[k] = static_cast<int32_t>(b.vertex[k]);
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
        // Split while the sub-patch's control points stray from the plane
        // of three of its corners by more than `flatness`.
        std::function<void(double, double, double, double, int, int)> split =
            [&](double u0, double u1, double v0, double v1, int du, int dv) {
                const bool canU = du < uSteps, canV = dv < vSteps;
                bool flat = true;
                if (canU || canV) flat = subPatchFlatness(u0, u1, v0, v1) <= flatness;
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
    auto mesh =
        std::make_shared<TriangleMesh>(std::move(vertices), std::move(normals), std::move(tris));
    mesh->setUvs(std::move(uvs));
    mesh_ = std::move(mesh);
}

}  // namespace frameray::scene
