// Torus, poly/cubic/quartic and blob shapes (scene/polynomial_shapes.h,
// scene/blob.h): exact hits, far-away rays, inside tests, normals, povray's
// coefficient order and the blob field.
#include "scene/polynomial_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "scene/blob.h"

namespace frameray::scene {
namespace {

std::vector<double> hits(const Shape& s, const Vec3& o, const Vec3& d) {
    std::vector<double> ts;
    s.allHits(Ray{o, d}, 0, kInfinity, ts);
    return ts;
}

TEST(Torus, HitsAlongAnAxis) {
    for (bool sturm : {false, true}) {
        const Torus torus(2, 0.5, sturm);
        auto ts = hits(torus, {-10, 0, 0}, {1, 0, 0});
        ASSERT_EQ(ts.size(), 4u);
        EXPECT_NEAR(ts[0], 7.5, 1e-12);
        EXPECT_NEAR(ts[1], 8.5, 1e-12);
        EXPECT_NEAR(ts[2], 11.5, 1e-12);
        EXPECT_NEAR(ts[3], 12.5, 1e-12);
        // A direction of length 2 halves every t.
        ts = hits(torus, {-10, 0, 0}, {2, 0, 0});
        ASSERT_EQ(ts.size(), 4u);
        EXPECT_NEAR(ts[0], 3.75, 1e-12);
        // Through the hole along y: nothing.
        EXPECT_TRUE(hits(torus, {0, -5, 0}, {0, 1, 0}).empty());
    }
}

TEST(Torus, FarAwayRayKeepsPrecision) {
    const Torus torus(2, 0.5, false);
    const auto ts = hits(torus, {-1e7, 0.3, 0}, {1, 0, 0});
    ASSERT_EQ(ts.size(), 4u);
    const double x = std::sqrt(0.25 - 0.09);  // tube half-width at height 0.3
    EXPECT_NEAR(ts[0], 1e7 - 2 - x, 1e-7);
    EXPECT_NEAR(ts[1], 1e7 - 2 + x, 1e-7);
}

TEST(Torus, GrazingRays) {
    // Rays tangent to the outer equator, to the top of the tube and to the
    // inner equator: a double root. Whatever the solver reports must lie at
    // the tangent point (once or as a pair), never elsewhere, never NaN.
    for (bool sturm : {false, true}) {
        const Torus torus(2, 0.5, sturm);
        struct Case {
            Vec3 origin, dir;
            double tangentT;
        };
        const Case cases[] = {{{-10, 0, 2.5}, {1, 0, 0}, 10},
                              {{-10, 0.5, 0}, {1, 0, 0}, 8},  // touches the top at x = -2 and x = 2
                              {{-10, 0, 1.5}, {1, 0, 0}, 10}};
        for (const Case& c : cases) {
            const auto ts = hits(torus, c.origin, c.dir);
            for (double t : ts) {
                ASSERT_TRUE(std::isfinite(t));
                const bool nearTangent = std::fabs(t - c.tangentT) < 1e-4 ||
                                         std::fabs(t - 12) < 1e-4 || std::fabs(t - 8) < 1e-4 ||
                                         std::fabs(t - (10 - std::sqrt(1.75))) < 1e-9 ||
                                         std::fabs(t - (10 + std::sqrt(1.75))) < 1e-9;
                EXPECT_TRUE(nearTangent) << "t = " << t << (sturm ? " (sturm)" : "");
            }
        }
        // Just outside the outer equator: a clean miss.
        EXPECT_TRUE(hits(torus, {-10, 0, 2.5 + 1e-9}, {1, 0, 0}).empty());
    }
}

TEST(Torus, InsideAndNormal) {
    const Torus torus(2, 0.5, false);
    EXPECT_TRUE(torus.inside({2, 0.4, 0}));
    EXPECT_FALSE(torus.inside({0, 0, 0}));
    EXPECT_FALSE(torus.inside({2, 0.6, 0}));
    const Vec3 n = torus.normal({0, 0, -2.5});
    EXPECT_NEAR(n.z, -1, 1e-12);
    const Vec3 top = torus.normal({-2, 0.5, 0});
    EXPECT_NEAR(top.y, 1, 1e-12);
}

TEST(Torus, SturmAgreesWithClosedForm) {
    const Torus closed(1.5, 0.3, false), sturm(1.5, 0.3, true);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 o(5 * u(rng), 5 * u(rng), 5 * u(rng));
        const Vec3 target(1.8 * u(rng), 0.3 * u(rng), 1.8 * u(rng));
        const auto a = hits(closed, o, target - o);
        const auto b = hits(sturm, o, target - o);
        // Tangent rays may differ (a double root once or twice); crossings
        // must agree.
        if (a.size() != b.size()) continue;
        for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 1e-7);
    }
}

TEST(PolynomialSurface, PovrayCoefficientOrder) {
    // Order 2 terms: x², xy, xz, x, y², yz, y, z², z, 1. The unit sphere:
    const PolynomialSurface sphere(2, {1, 0, 0, 0, 1, 0, 0, 1, 0, -1}, false, "poly");
    auto ts = hits(sphere, {0, 0, -5}, {0, 0, 1});
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 4, 1e-12);
    EXPECT_NEAR(ts[1], 6, 1e-12);
    EXPECT_TRUE(sphere.inside({0.5, 0, 0}));
    // Quartic piriform from shapesq.inc: 4x⁴ - 4x³ + y² + z² (A1, A4, A26, A33).
    std::vector<double> c(35, 0);
    c[0] = 4;
    c[3] = -4;
    c[25] = 1;
    c[32] = 1;
    const PolynomialSurface piriform(4, c, false, "quartic");
    const Vec3 p(0.5, 0.2, -0.1);
    EXPECT_NEAR(piriform.value(p), 4 * 0.0625 - 4 * 0.125 + 0.04 + 0.01, 1e-15);
    // The mixed cubic term xyz is coefficient 6 of a cubic.
    std::vector<double> k(20, 0);
    k[5] = 1;
    const PolynomialSurface xyz(3, k, false, "cubic");
    EXPECT_NEAR(xyz.value({2, 3, 5}), 30, 1e-12);
    const Vec3 g = xyz.normal({1, 1, 1});
    EXPECT_NEAR(g.x, 1 / std::sqrt(3.0), 1e-12);
}

// Rays through the hole, past the rim and grazing the tube: the crossings
// are those of the inside test marched along the ray (guards the thick
// cylinder test that skips the quartic).
TEST(Torus, HitsAreTheCrossingsOfTheInsideTest) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    int crossings = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const double major = 1 + 0.5 * (u(rng) + 1), minor = 0.2 + 0.3 * (u(rng) + 1);
        const Torus torus(major, minor, trial % 2 == 1);
        Vec3 from(u(rng) * 3, u(rng) * 3, -6);
        Vec3 to(u(rng) * (major + minor), u(rng) * minor * 1.5, u(rng) * (major + minor));
        if (trial % 4 >= 2) {
            // Steeply down past the inner edge of the tube, in and out of the hole.
            const double angle = u(rng) * 3.2, radius = major - minor * (1 + 0.3 * u(rng));
            to = Vec3(radius * std::cos(angle), u(rng) * minor, radius * std::sin(angle));
            from = to + Vec3(u(rng) * 0.3, 6, u(rng) * 0.3);
        }
        const Ray ray{from, normalize(to - from)};
        const auto ts = hits(torus, ray.origin, ray.direction);
        std::vector<double> marched;
        constexpr int kSteps = 12000;
        constexpr double kEnd = 12, kStep = kEnd / kSteps;
        bool before = torus.inside(ray.at(0));
        for (int k = 1; k <= kSteps; ++k) {
            const bool now = torus.inside(ray.at(k * kStep));
            if (now != before) marched.push_back((k - 0.5) * kStep);
            before = now;
        }
        crossings += static_cast<int>(marched.size());
        ASSERT_EQ(ts.size(), marched.size()) << "trial " << trial;
        for (std::size_t i = 0; i < ts.size(); ++i)
            EXPECT_NEAR(ts[i], marched[i], kStep) << "trial " << trial;
    }
    EXPECT_GT(crossings, 200);
}

TEST(PolynomialSurface, FarAwayRay) {
    const PolynomialSurface sphere(2, {1, 0, 0, 0, 1, 0, 0, 1, 0, -1}, true, "poly");
    const auto ts = hits(sphere, {0, 0.6, -1e8}, {0, 0, 1});
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 1e8 - 0.8, 1e-6);
    EXPECT_NEAR(ts[1], 1e8 + 0.8, 1e-6);
}

TEST(Blob, SingleSphereComponent) {
    Blob::Component c;
    c.a = {1, 0, 0};
    c.radius = 2;
    c.strength = 1;
    // (1 - r²/4)² = 0.25  =>  r² = 2.
    for (bool sturm : {false, true}) {
        const Blob blob({c}, 0.25, sturm);
        const auto ts = hits(blob, {1, 0, -10}, {0, 0, 1});
        ASSERT_EQ(ts.size(), 2u);
        EXPECT_NEAR(ts[0], 10 - std::sqrt(2.0), 1e-12);
        EXPECT_NEAR(ts[1], 10 + std::sqrt(2.0), 1e-12);
        EXPECT_TRUE(blob.inside({1, 1, 0}));
        EXPECT_FALSE(blob.inside({1, 1.5, 0}));
        EXPECT_NEAR(blob.normal({1, std::sqrt(2.0), 0}).y, 1, 1e-12);
    }
}

TEST(Blob, CylinderComponentIsACapsule) {
    Blob::Component c;
    c.kind = Blob::Component::Kind::Cylinder;
    c.a = {-1, 0, 0};
    c.b = {1, 0, 0};
    c.radius = 1;
    c.strength = 2;
    // 2 (1 - d²)² = 0.5  =>  d² = 0.5.
    const Blob blob({c}, 0.5, false);
    const double r = std::sqrt(0.5);
    auto ts = hits(blob, {0, -5, 0}, {0, 1, 0});  // across the body
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 5 - r, 1e-12);
    ts = hits(blob, {-5, 0, 0}, {1, 0, 0});  // along the axis, through both caps
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 4 - r, 1e-12);
    EXPECT_NEAR(ts[1], 6 + r, 1e-12);
    ts = hits(blob, {1.3, -5, 0}, {0, 1, 0});  // through a cap
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 5 - std::sqrt(0.5 - 0.09), 1e-12);
}

TEST(Blob, TwoComponentsMerge) {
    Blob::Component a, b;
    a.a = {-0.6, 0, 0};
    b.a = {0.6, 0, 0};
    a.radius = b.radius = 1;
    const Blob blob({a, b}, 0.6, false);
    // Between the centres the fields add up above the threshold.
    EXPECT_TRUE(blob.inside({0, 0, 0}));
    const auto ts = hits(blob, {-5, 0, 0}, {1, 0, 0});
    ASSERT_EQ(ts.size(), 2u);  // one merged body
    EXPECT_NEAR(blob.density(Ray{{-5, 0, 0}, {1, 0, 0}}.at(ts[0])), 0.6, 1e-12);
}

// Every crossing of the threshold found by marching the field along the ray
// is a hit, and nothing else is: random blobs of spheres and capsules (some
// negative) under random rays. Guards the spans allHits skips as unable to
// reach the threshold.
TEST(Blob, HitsAreTheCrossingsOfTheMarchedField) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    const auto point = [&] { return Vec3(u(rng), u(rng), u(rng)); };
    int crossings = 0;
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<Blob::Component> comps(2 + trial % 5);
        for (std::size_t i = 0; i < comps.size(); ++i) {
            Blob::Component& c = comps[i];
            c.kind = i % 3 == 2 ? Blob::Component::Kind::Cylinder : Blob::Component::Kind::Sphere;
            c.a = point();
            c.b = c.a + point() * 0.8;
            c.radius = 0.4 + 0.4 * (u(rng) + 1);
            c.strength = i % 4 == 3 ? -0.5 : 0.5 + u(rng) * 0.4 + 0.4;
        }
        const double threshold = 0.3 + 0.2 * (u(rng) + 1);
        const Blob blob(comps, threshold, trial % 2 == 1);
        const Ray ray{point() * 0.5 + Vec3(0, 0, -4), normalize(point() * 0.3 + Vec3(0, 0, 1))};
        const auto ts = hits(blob, ray.origin, ray.direction);
        std::vector<double> marched;
        constexpr int kSteps = 8000;
        constexpr double kEnd = 8, kStep = kEnd / kSteps;
        double before = blob.density(ray.at(0)) - threshold;
        for (int k = 1; k <= kSteps; ++k) {
            const double now = blob.density(ray.at(k * kStep)) - threshold;
            if ((before > 0) != (now > 0)) marched.push_back((k - 0.5) * kStep);
            before = now;
        }
        crossings += static_cast<int>(marched.size());
        ASSERT_EQ(ts.size(), marched.size()) << "trial " << trial;
        for (std::size_t i = 0; i < ts.size(); ++i)
            EXPECT_NEAR(ts[i], marched[i], kStep) << "trial " << trial;
    }
    EXPECT_GT(crossings, 100);  // the rays do meet the blobs
}

}  // namespace
}  // namespace frameray::scene
