// Bounds of polynomial surfaces (scene/polynomial_bounds.h): closed
// surfaces get a box holding them and little more, open ones stay
// unbounded, and the box culls rays without changing any hit.
#include "scene/polynomial_bounds.h"

#include <gtest/gtest.h>

#include <random>

#include "scene/polynomial_shapes.h"

namespace frameray::scene {
namespace {

// pawns.pov's first quartic: (x² + y² + z²)² - 738 (x² + z²) + 162 y² + 6561,
// the torus R = 15, r = 12 (povray's coefficient order).
std::vector<double> pawnTorus() {
    return {1.0, 0.0,   0.0, 0.0, 2.0, 0.0, 0.0, 2.0, 0.0,    -738.0, 0.0,   0.0,
            0.0, 0.0,   0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0,    0.0,    0.0,   2.0,
            0.0, 162.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -738.0, 0.0,    6561.0};
}

void expectHolds(const Bounds& box, const Vec3& lo, const Vec3& hi, double slack) {
    for (int a = 0; a < 3; ++a) {
        EXPECT_LE(box.lo[a], lo[a]) << "axis " << a;
        EXPECT_GE(box.hi[a], hi[a]) << "axis " << a;
        EXPECT_GE(box.lo[a], lo[a] - slack) << "axis " << a;
        EXPECT_LE(box.hi[a], hi[a] + slack) << "axis " << a;
    }
}

TEST(PolynomialBounds, TorusQuarticGetsATightBox) {
    const PolynomialSurface torus(4, pawnTorus(), true, "quartic");
    ASSERT_TRUE(torus.bounds().isFinite());
    expectHolds(torus.bounds(), {-27, -12, -27}, {27, 12, 27}, 2.0);
    ASSERT_TRUE(torus.insideBounds().isFinite());
}

TEST(PolynomialBounds, SphereAsPoly) {
    // x² + y² + z² - 4 (poly order 2: x², xy, xz, x, y², yz, y, z², z, 1).
    const PolynomialSurface sphere(2, {1, 0, 0, 0, 1, 0, 0, 1, 0, -4}, false, "poly");
    ASSERT_TRUE(sphere.bounds().isFinite());
    expectHolds(sphere.bounds(), {-2, -2, -2}, {2, 2, 2}, 0.2);
    // Offset: (x - 3)² + y² + z² - 1 = x² - 6x + y² + z² + 8.
    const PolynomialSurface shifted(2, {1, 0, 0, -6, 1, 0, 0, 1, 0, 8}, false, "poly");
    expectHolds(shifted.bounds(), {2, -1, -1}, {4, 1, 1}, 0.5);
}

TEST(PolynomialBounds, OpenSurfacesStayUnbounded) {
    // Cylinder x² + z² - 1: no y² term at the top degree.
    EXPECT_FALSE(
        PolynomialSurface(2, {1, 0, 0, 0, 0, 0, 0, 1, 0, -1}, false, "poly").bounds().isFinite());
    // Paraboloid x² + z² - y.
    EXPECT_FALSE(
        PolynomialSurface(2, {1, 0, 0, 0, 0, 0, -1, 1, 0, 0}, false, "poly").bounds().isFinite());
    // Hyperboloid x² - y² + z² - 1 (a negative top-degree coefficient).
    EXPECT_FALSE(
        PolynomialSurface(2, {1, 0, 0, 0, -1, 0, 0, 1, 0, -1}, false, "poly").bounds().isFinite());
    // Negative far away: the inside is everything outside a sphere.
    EXPECT_FALSE(
        PolynomialSurface(2, {-1, 0, 0, 0, -1, 0, 0, -1, 0, 1}, false, "poly").bounds().isFinite());
    // Odd degree: a cubic always reaches infinity.
    std::vector<double> cubic(20, 0.0);
    cubic[0] = 1;
    cubic[19] = -1;
    EXPECT_FALSE(PolynomialSurface(3, cubic, false, "cubic").bounds().isFinite());
}

TEST(PolynomialBounds, NoSurfaceGivesAnEmptyBox) {
    // x² + y² + z² + 1 > 0 everywhere.
    const PolynomialSurface none(2, {1, 0, 0, 0, 1, 0, 0, 1, 0, 1}, false, "poly");
    EXPECT_TRUE(none.bounds().isEmpty());
}

TEST(PolynomialBounds, EveryHitLiesInTheBoxAndCullingLosesNoHit) {
    // The box culls rays in allHits: random rays still find what the
    // torus shape (bounded by its own sphere) finds.
    const PolynomialSurface bounded(4, pawnTorus(), true, "quartic");
    const Torus torus(15, 12, true);
    ASSERT_TRUE(bounded.bounds().isFinite());
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    int hitRays = 0;
    for (int n = 0; n < 2000; ++n) {
        const Vec3 o(u(rng) * 60, u(rng) * 60, u(rng) * 60);
        const Vec3 d(u(rng), u(rng), u(rng));
        std::vector<double> ts;
        bounded.allHits(Ray{o, d}, 1e-6, kInfinity, ts);
        for (const double t : ts) {
            const Vec3 p = o + d * t;
            for (int a = 0; a < 3; ++a) {
                EXPECT_GE(p[a], bounded.bounds().lo[a]);
                EXPECT_LE(p[a], bounded.bounds().hi[a]);
            }
        }
        std::vector<double> expected;
        torus.allHits(Ray{o, d}, 1e-6, kInfinity, expected);
        ASSERT_EQ(ts.size(), expected.size()) << n;
        for (size_t i = 0; i < ts.size(); ++i) EXPECT_NEAR(ts[i], expected[i], 1e-6 * (1 + ts[i]));
        hitRays += !ts.empty();
    }
    EXPECT_GT(hitRays, 100);
}

}  // namespace
}  // namespace frameray::scene
