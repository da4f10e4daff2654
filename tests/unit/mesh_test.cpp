// Triangle meshes, height fields and bicubic patches: ray hits, normals,
// inside tests and the heights povray 3.7 gives (measured with trace()).
#include "scene/mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <tuple>

#include "scene/bicubic_patch.h"
#include "scene/height_field.h"
#include "scene/shape_math.h"

using namespace frameray;
using namespace frameray::scene;

namespace {

// A closed unit cube from -1 to 1 as 12 triangles.
std::shared_ptr<const TriangleMesh> cubeMesh() {
    std::vector<Vec3> v;
    for (int i = 0; i < 8; ++i) v.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    const uint32_t faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 2, 6, 4},
                                  {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}};
    std::vector<MeshTriangle> tris;
    for (const auto& f : faces) {
        MeshTriangle a, b;
        a.vertex = {f[0], f[1], f[2]};
        b.vertex = {f[0], f[2], f[3]};
        tris.push_back(a);
        tris.push_back(b);
    }
    return std::make_shared<const TriangleMesh>(std::move(v), std::vector<Vec3>{}, std::move(tris));
}

}  // namespace

TEST(Mesh, FirstAndAllHitsOfACube) {
    MeshShape cube(cubeMesh(), TriangleMesh::kAllGroups, false, {});
    double t;
    ASSERT_TRUE(cube.firstHit({{0.2, 0.3, -5}, {0, 0, 1}}, 0, kInfinity, t));
    EXPECT_DOUBLE_EQ(t, 4);
    std::vector<double> ts;
    cube.allHits({{0.2, 0.3, -5}, {0, 0, 2}}, 0, kInfinity, ts);
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_DOUBLE_EQ(ts[0], 2);
    EXPECT_DOUBLE_EQ(ts[1], 3);
    EXPECT_FALSE(cube.firstHit({{2, 0, -5}, {0, 0, 1}}, 0, kInfinity, t));
    // tMax cuts hits off.
    EXPECT_FALSE(cube.firstHit({{0.2, 0.3, -5}, {0, 0, 1}}, 0, 3.5, t));
    const Vec3 n = cube.normal({0.2, 0.3, -1});
    EXPECT_NEAR(std::fabs(n.z), 1, 1e-12);
}

TEST(Mesh, InsideNeedsAnInsideVector) {
    MeshShape patch(cubeMesh(), TriangleMesh::kAllGroups, false, {});
    EXPECT_TRUE(patch.isPatch());
    EXPECT_FALSE(patch.inside({0, 0, 0}));
    MeshShape solid(cubeMesh(), TriangleMesh::kAllGroups, true, {0.3, 0.7, 0.2});
    EXPECT_FALSE(solid.isPatch());
    EXPECT_TRUE(solid.inside({0.1, -0.2, 0.3}));
    EXPECT_FALSE(solid.inside({1.5, 0, 0}));
}

TEST(Mesh, ManyTrianglesAgreeWithBruteForce) {
    // A random triangle soup: the BVH must find what testing every
    // triangle finds.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-10, 10);
    std::vector<Vec3> v;
    std::vector<MeshTriangle> tris;
    for (uint32_t i = 0; i < 600; ++i) {
        const Vec3 c(u(rng), u(rng), u(rng));
        for (int k = 0; k < 3; ++k) v.push_back(c + Vec3(u(rng), u(rng), u(rng)) * 0.1);
        MeshTriangle t;
        t.vertex = {3 * i, 3 * i + 1, 3 * i + 2};
        tris.push_back(t);
    }
    TriangleMesh mesh(v, {}, tris);
    for (int r = 0; r < 300; ++r) {
        const Ray ray{{u(rng), u(rng), -30}, normalize(Vec3(u(rng) * 0.05, u(rng) * 0.05, 1))};
        double best = kInfinity;
        for (const MeshTriangle& t : tris) {
            TriangleMesh one({v[t.vertex[0]], v[t.vertex[1]], v[t.vertex[2]]}, {},
                             {MeshTriangle{{0, 1, 2}}});
            double h;
            if (one.firstHit(ray, 0, best, h, TriangleMesh::kAllGroups)) best = h;
        }
        double t;
        const bool hit = mesh.firstHit(ray, 0, kInfinity, t, TriangleMesh::kAllGroups);
        EXPECT_EQ(hit, best < kInfinity);
        if (hit) {
            EXPECT_DOUBLE_EQ(t, best);
        }
    }
}

TEST(Mesh, TextureGroupsSplitTheTriangles) {
    std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    MeshTriangle a, b;
    a.vertex = {0, 1, 2};
    a.texture = 1;
    b.vertex = {1, 3, 2};
    auto mesh = std::make_shared<const TriangleMesh>(v, std::vector<Vec3>{},
                                                     std::vector<MeshTriangle>{a, b});
    ASSERT_EQ(mesh->groupCount(), 2u);
    EXPECT_EQ(mesh->groupTexture(0), -1);
    EXPECT_EQ(mesh->groupTexture(1), 1);
    double t;
    const Ray lowerLeft{{0.2, 0.2, -1}, {0, 0, 1}};
    EXPECT_TRUE(mesh->firstHit(lowerLeft, 0, kInfinity, t, 1));
    EXPECT_FALSE(mesh->firstHit(lowerLeft, 0, kInfinity, t, 0));
}

TEST(Mesh, SmoothNormalsInterpolate) {
    std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    std::vector<Vec3> n{{0, 0, -1}, {1, 0, -1}, {0, 1, -1}};
    MeshTriangle t;
    t.vertex = {0, 1, 2};
    t.normal = {0, 1, 2};
    TriangleMesh mesh(v, n, {t});
    const Vec3 at0 = mesh.normal({0, 0, 0}, TriangleMesh::kAllGroups);
    EXPECT_NEAR(at0.z, -1, 1e-12);
    const Vec3 mid = mesh.normal({0.5, 0, 0}, TriangleMesh::kAllGroups);
    const Vec3 expected = normalize(normalize(Vec3(0, 0, -1)) + normalize(Vec3(1, 0, -1)));
    EXPECT_NEAR(mid.x, expected.x, 1e-12);
    EXPECT_NEAR(mid.z, expected.z, 1e-12);
}

TEST(HeightField, HeightsAsPovrayGivesThem) {
    // 3 x 2 grid, rows from the top: the bottom row lies at z = 0.
    // Heights are 16-bit values over 65536 (povray: an 8-bit 200 is 51400).
    std::vector<uint16_t> h{0, 257, 0, 0, 51400, 0};
    HeightField hf(3, 2, h, false, 0);
    EXPECT_DOUBLE_EQ(hf.sample(1, 0), 51400.0 / 65536);
    EXPECT_DOUBLE_EQ(hf.sample(1, 1), 257.0 / 65536);
    EXPECT_DOUBLE_EQ(hf.heightAt(0.5, 0), 51400.0 / 65536);
    double t;
    ASSERT_TRUE(hf.firstHit({{0.5, 5, 0.5}, {0, -1, 0}}, 0, kInfinity, t));
    EXPECT_NEAR(5 - t, (51400.0 + 257.0) / 2 / 65536, 1e-12);
    EXPECT_TRUE(hf.inside({0.5, 0.1, 0.01}));
    EXPECT_FALSE(hf.inside({0.5, 0.9, 0.5}));
    EXPECT_TRUE(hf.inside({0.5, -3, 0.5}));  // no floor, as in povray
    EXPECT_FALSE(hf.inside({1.5, -3, 0.5}));
}

TEST(HeightField, CellsSplitAlongTheRisingDiagonal) {
    // povray cuts a cell from (x + 1, z) to (x, z + 1): with only the
    // corner at (0, 0) raised, the cell's centre stays at 0.
    std::vector<uint16_t> h{0, 0, 65280, 0};  // top row, then bottom row
    HeightField hf(2, 2, h, false, 0);
    EXPECT_DOUBLE_EQ(hf.heightAt(0.5, 0.5), 0);
    EXPECT_NEAR(hf.heightAt(0.25, 0.25), 0.5 * 65280 / 65536, 1e-12);
    double t;
    ASSERT_TRUE(hf.firstHit({{0.25, 5, 0.25}, {0, -1, 0}}, 0, kInfinity, t));
    EXPECT_NEAR(5 - t, 0.5 * 65280 / 65536, 1e-12);
}

TEST(HeightField, WaterLevelHidesWhatIsBelow) {
    std::vector<uint16_t> h{0, 0, 65280, 0};
    HeightField hf(2, 2, h, false, 0.3);
    double t;
    EXPECT_TRUE(hf.firstHit({{0.1, 5, 0.1}, {0, -1, 0}}, 0, kInfinity, t));
    EXPECT_FALSE(hf.firstHit({{0.6, 5, 0.6}, {0, -1, 0}}, 0, kInfinity, t));
}

// Every hit of a height field's triangles, cell by cell, built as
// height_field.h describes them (the search's answer must be these, bit
// for bit, whichever cells its quadtree walk visits).
std::vector<double> bruteForceHits(const HeightField& hf, int w, int h, double water,
                                   const Ray& ray, double tMin, double tMax) {
    const double sx = 1.0 / (w - 1), sz = 1.0 / (h - 1);
    auto corner = [&](int i, int k) { return Vec3(i * sx, hf.sample(i, k), k * sz); };
    std::vector<double> ts;
    for (int k = 0; k + 1 < h; ++k)
        for (int i = 0; i + 1 < w; ++i) {
            const Vec3 c00 = corner(i, k), c10 = corner(i + 1, k), c01 = corner(i, k + 1),
                       c11 = corner(i + 1, k + 1);
            const Vec3 tri[2][3] = {{c00, c10, c01}, {c10, c11, c01}};
            for (const auto& t : tri) {
                double hit;
                if (!detail::hitTriangle(ray, t[0], t[1], t[2], tMin, tMax, hit)) continue;
                if (water > 0 && ray.origin.y + ray.direction.y * hit < water) continue;
                ts.push_back(hit);
            }
        }
    std::sort(ts.begin(), ts.end());
    return ts;
}

TEST(HeightField, QuadtreeWalkFindsWhatTestingEveryCellFinds) {
    // Random fields (odd sizes: partial quadtree nodes at the edges), rays
    // of every kind: steep, grazing, from below, axis-parallel, along grid
    // lines and through grid points, some starting inside the box.
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> unit(0, 1), wide(-0.5, 1.5);
    for (const auto& [w, h, water] : {std::tuple{37, 21, 0.0}, std::tuple{16, 16, 0.35},
                                      std::tuple{2, 9, 0.0}, std::tuple{65, 3, 0.2}}) {
        std::vector<uint16_t> heights(static_cast<size_t>(w * h));
        for (auto& v : heights) v = static_cast<uint16_t>(unit(rng) * 50000 + 5000);
        const HeightField hf(w, h, heights, false, water);
        int hits = 0;
        for (int n = 0; n < 4000; ++n) {
            Vec3 o{wide(rng), unit(rng) * 2 - 0.3, wide(rng)};
            Vec3 d{unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5};
            switch (n % 8) {
                case 1:
                    d.y *= 0.02;
                    break;  // grazing
                case 2:
                    d = {0, -1, 0};
                    break;  // straight down
                case 3:
                    d.x = 0;
                    o.x = (n % w) / double(w - 1);
                    break;  // along a grid line
                case 4:
                    d.z = 0;
                    o.z = (n % h) / double(h - 1);
                    break;
                case 5:  // through a grid point
                    o = Vec3((n % w) / double(w - 1), hf.sample(n % w, n % h),
                             (n % h) / double(h - 1)) -
                        d * 3;
                    break;
                case 6:
                    d.y = 0;
                    o.y = unit(rng);
                    break;  // horizontal
                default:
                    break;
            }
            const Ray ray{o, d};
            const double tMin = n % 3 == 0 ? 0.5 : 0, tMax = n % 5 == 0 ? 2.5 : kInfinity;
            const auto all = bruteForceHits(hf, w, h, water, ray, tMin, tMax);
            double t = -1;
            const bool found = hf.firstHit(ray, tMin, tMax, t);
            ASSERT_EQ(found, !all.empty()) << w << "x" << h << " ray " << n;
            if (found) {
                EXPECT_EQ(t, all.front()) << w << "x" << h << " ray " << n;
                ++hits;
            }
            std::vector<double> ts;
            hf.allHits(ray, tMin, tMax, ts);
            EXPECT_EQ(ts, all) << w << "x" << h << " ray " << n;
        }
        EXPECT_GT(hits, 500);
    }
}

TEST(BicubicPatch, CornersAndDiagonal) {
    // A flat patch with one raised corner (measured against povray:
    // u_steps 1, v_steps 1 puts the centre at 1/64 and cuts each
    // sub-patch along (u0, v0)-(u1, v1)).
    std::array<Vec3, 16> p;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) p[static_cast<size_t>(4 * r + c)] = Vec3(c / 3.0, 0, r / 3.0);
    p[15].y = 1;
    BicubicPatch patch(p, 1, 1, 0);
    EXPECT_EQ(patch.triangleCount(), 8u);
    double t;
    ASSERT_TRUE(patch.firstHit({{0.5, 5, 0.5}, {0, -1, 0}}, 0, kInfinity, t));
    EXPECT_NEAR(5 - t, 1.0 / 64, 1e-12);
    ASSERT_TRUE(patch.firstHit({{0.25, 5, 0.75}, {0, -1, 0}}, 0, kInfinity, t));
    EXPECT_NEAR(5 - t, 1.0 / 16, 1e-12);
}

TEST(BicubicPatch, FlatnessStopsSplittingFlatParts) {
    // The raised-corner patch with flatness 0.1 and 3 steps, as povray's
    // trace() shows it: [0, 1/2]^2 stays one sub-patch (its centre lies on
    // the diagonal, at 1/128), [1/2, 1]^2 is split.
    std::array<Vec3, 16> p;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) p[static_cast<size_t>(4 * r + c)] = Vec3(c / 3.0, 0, r / 3.0);
    p[15].y = 1;
    BicubicPatch patch(p, 3, 3, 0.1);
    double t;
    ASSERT_TRUE(patch.firstHit({{0.25, 5, 0.25}, {0, -1, 0}}, 0, kInfinity, t));
    EXPECT_NEAR(5 - t, 1.0 / 128, 1e-12);
    ASSERT_TRUE(patch.firstHit({{0.75, 5, 0.75}, {0, -1, 0}}, 0, kInfinity, t));
    EXPECT_NEAR(5 - t, 0.75 * 0.75 * 0.75 * 0.75 * 0.75 * 0.75, 1e-12);
    ASSERT_TRUE(patch.firstHit({{0.625, 5, 0.625}, {0, -1, 0}}, 0, kInfinity, t));
    EXPECT_NEAR(5 - t, 0.096802, 1e-6);
}

TEST(BicubicPatch, FlatnessMeasuresWhereThePatchIsPlaced) {
    // povray measures flatness on the moved control points: scaled by 10,
    // the raised-corner patch is split where it was flat enough.
    std::array<Vec3, 16> p;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) p[static_cast<size_t>(4 * r + c)] = Vec3(c / 3.0, 0, r / 3.0);
    p[15].y = 1;
    const BicubicPatch patch(p, 3, 3, 0.1);
    const auto placed =
        std::dynamic_pointer_cast<const BicubicPatch>(patch.placedBy(Transform::scale(Vec3(10))));
    ASSERT_TRUE(placed);
    EXPECT_GT(placed->triangleCount(), patch.triangleCount());
    EXPECT_EQ(BicubicPatch(p, 3, 3, 0).placedBy(Transform::scale(Vec3(10))), nullptr);
}

TEST(Mesh, NormalAndUvAtOnceEqualTheSeparateQueries) {
    // A smooth, uv-mapped random terrain: the combined query (one triangle
    // search) must give bit for bit what normal() and uv() give.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> h(-0.3, 0.3);
    const uint32_t n = 12;
    std::vector<Vec3> v, normals;
    std::vector<std::array<double, 2>> uvs;
    for (uint32_t z = 0; z <= n; ++z)
        for (uint32_t x = 0; x <= n; ++x) {
            v.emplace_back(x, h(rng), z);
            normals.push_back(normalize(Vec3(h(rng), 1, h(rng))));
            uvs.push_back({x / double(n), z / double(n)});
        }
    std::vector<MeshTriangle> tris;
    for (uint32_t z = 0; z < n; ++z)
        for (uint32_t x = 0; x < n; ++x) {
            const uint32_t a = z * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
            for (const auto& f :
                 {std::array<uint32_t, 3>{a, b, d}, std::array<uint32_t, 3>{a, d, c}}) {
                MeshTriangle t;
                t.vertex = f;
                t.normal = {int32_t(f[0]), int32_t(f[1]), int32_t(f[2])};
                t.uv = {int32_t(f[0]), int32_t(f[1]), int32_t(f[2])};
                tris.push_back(t);
            }
        }
    auto built = std::make_shared<TriangleMesh>(v, normals, tris);
    built->setUvs(uvs);
    const MeshShape shape(built, TriangleMesh::kAllGroups, false, {});
    const Transform toWorld = Transform::scale({2, 0.5, 1}).then(Transform::rotate({10, 30, 0}));
    std::uniform_real_distribution<double> at(0.01, n - 0.01);
    int hits = 0;
    for (int r = 0; r < 500; ++r) {
        double t;
        const Ray ray{{at(rng), 5, at(rng)}, normalize(Vec3(h(rng), -1, h(rng)))};
        if (!shape.firstHit(ray, 0, kInfinity, t)) continue;
        ++hits;
        const Vec3 p = ray.at(t);
        double u1 = -1, v1 = -1, u2 = -2, v2 = -2;
        bool hasUv = false;
        const Vec3 both = shape.worldNormalUv(p, toWorld, hasUv, u2, v2);
        ASSERT_TRUE(shape.uv(p, u1, v1));
        const Vec3 alone = shape.worldNormal(p, toWorld);
        EXPECT_TRUE(hasUv);
        EXPECT_EQ(both.x, alone.x);
        EXPECT_EQ(both.y, alone.y);
        EXPECT_EQ(both.z, alone.z);
        EXPECT_EQ(u1, u2);
        EXPECT_EQ(v1, v2);
    }
    EXPECT_GT(hits, 400);
}

TEST(BicubicPatch, NormalAndUvAtOnceEqualTheSeparateQueries) {
    std::array<Vec3, 16> p;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) p[static_cast<size_t>(4 * r + c)] = Vec3(c / 3.0, 0, r / 3.0);
    p[5].y = 0.7;
    p[15].y = 1;
    const BicubicPatch patch(p, 3, 3, 0);
    const Transform toWorld = Transform::rotate({20, 0, 40});
    for (double x = 0.05; x < 1; x += 0.1)
        for (double z = 0.05; z < 1; z += 0.1) {
            double t;
            const Ray ray{{x, 5, z}, {0, -1, 0}};
            ASSERT_TRUE(patch.firstHit(ray, 0, kInfinity, t));
            const Vec3 q = ray.at(t);
            double u1, v1, u2, v2;
            bool hasUv = false;
            const Vec3 both = patch.worldNormalUv(q, toWorld, hasUv, u2, v2);
            ASSERT_TRUE(patch.uv(q, u1, v1));
            const Vec3 alone = patch.worldNormal(q, toWorld);
            EXPECT_TRUE(hasUv);
            EXPECT_EQ(both.x, alone.x);
            EXPECT_EQ(both.y, alone.y);
            EXPECT_EQ(both.z, alone.z);
            EXPECT_EQ(u1, u2);
            EXPECT_EQ(v1, v2);
        }
}
