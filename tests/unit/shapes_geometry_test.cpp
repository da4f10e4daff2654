// Cylinders, cones, discs, triangles, quadrics and julia fractals: exact hits, normals,
// inside answers and bounds in object space.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/flat_shapes.h"
#include "scene/julia_fractal.h"
#include "scene/quadric.h"
#include "scene/revolved_shapes.h"

using namespace frameray;
using namespace frameray::scene;

namespace {

std::vector<double> hits(const Shape& s, const Ray& r) {
    std::vector<double> ts;
    s.allHits(r, 0, kInfinity, ts);
    return ts;
}

void expectVec(const Vec3& a, const Vec3& b, double tol = 1e-12) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

}  // namespace

TEST(Cylinder, SideAndCapHits) {
    Cylinder c({0, 0, 0}, {0, 2, 0}, 1, false);
    // Through the side, perpendicular to the axis.
    auto ts = hits(c, {{-5, 1, 0}, {1, 0, 0}});
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_DOUBLE_EQ(ts[0], 4);
    EXPECT_DOUBLE_EQ(ts[1], 6);
    // Along the axis: in through the base cap, out through the top cap.
    ts = hits(c, {{0.5, -3, 0}, {0, 1, 0}});
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_DOUBLE_EQ(ts[0], 3);
    EXPECT_DOUBLE_EQ(ts[1], 5);
    // Diagonal: in through the cap, out through the side.
    ts = hits(c, {{0, 3, 0}, {0.5, -1, 0}});
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_DOUBLE_EQ(ts[0], 1);
    EXPECT_DOUBLE_EQ(ts[1], 2);
    // Grazing the rim: cap and side meet in one crossing.
    EXPECT_EQ(hits(c, {{0, 3, 0}, {1, -1, 0}}).size(), 1u);
    expectVec(c.normal({1, 1, 0}), {1, 0, 0});
    expectVec(c.normal({0.2, 2, 0.1}), {0, 1, 0});
    expectVec(c.normal({0.2, 0, 0.1}), {0, -1, 0});
    // Misses beyond the ends.
    EXPECT_TRUE(hits(c, {{-5, 2.5, 0}, {1, 0, 0}}).empty());
}

TEST(Cylinder, OpenHasNoCapsButTheSameInside) {
    Cylinder c({0, 0, 0}, {0, 2, 0}, 1, true);
    EXPECT_TRUE(hits(c, {{0.5, -3, 0}, {0, 1, 0}}).empty());
    auto ts = hits(c, {{0, 3, 0}, {0.5, -1, 0}});
    ASSERT_EQ(ts.size(), 1u);
    EXPECT_DOUBLE_EQ(ts[0], 2);
    expectVec(c.normal({0.6, 2, 0.8}), {0.6, 0, 0.8});  // the rim belongs to the side
    EXPECT_TRUE(c.inside({0, 1, 0}));
    EXPECT_FALSE(c.inside({0, 2.1, 0}));
}

TEST(Cylinder, InsideExcludesATinySkin) {
    // povray: a cylinder 1e-12 wider does not contain the surface, 1e-10 does.
    Cylinder c({0, -1, 0}, {0, 1, 0}, 1, false);
    EXPECT_TRUE(c.inside({0.999, 0, 0}));
    EXPECT_FALSE(c.inside({1, 0, 0}));
    EXPECT_FALSE(c.inside({1 - 1e-12, 0, 0}));
    EXPECT_TRUE(Cylinder({0, -1, 0}, {0, 1, 0}, 1 + 1e-10, false).inside({1, 0, 0}));
    EXPECT_FALSE(c.inside({0, 1, 0}));
    EXPECT_FALSE(c.inside({0, -1.5, 0}));
}

TEST(Cylinder, SlantedAxisBounds) {
    Cylinder c({0, 0, 0}, {3, 4, 0}, 1, false);
    const Bounds b = c.bounds();
    // The end circles are normal to (0.6, 0.8, 0): they reach 0.8 along x,
    // 0.6 along y, 1 along z.
    expectVec(b.lo, {-0.8, -0.6, -1});
    expectVec(b.hi, {3.8, 4.6, 1});
    // A hit on the slanted side, straight down the z axis at the middle.
    auto ts = hits(c, {{1.5, 2, -5}, {0, 0, 1}});
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 4, 1e-12);
    EXPECT_NEAR(ts[1], 6, 1e-12);
    expectVec(c.normal({1.5, 2, -1}), {0, 0, -1});
}

TEST(Cone, SideHitsAndNormals) {
    // Radius 1 at y = 0 shrinking to 0.5 at y = 1.
    Cone k({0, 0, 0}, 1, {0, 1, 0}, 0.5, false);
    auto ts = hits(k, {{-5, 0.5, 0}, {1, 0, 0}});
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_DOUBLE_EQ(ts[0], 4.25);
    EXPECT_DOUBLE_EQ(ts[1], 5.75);
    // Side normal: radial out and tilted up by the slope 0.5.
    expectVec(k.normal({0.75, 0.5, 0}), normalize(Vec3{1, 0.5, 0}));
    // The caps.
    ts = hits(k, {{0, -2, 0}, {0, 1, 0}});
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_DOUBLE_EQ(ts[0], 2);
    EXPECT_DOUBLE_EQ(ts[1], 3);
    expectVec(k.normal({0.1, 1, 0}), {0, 1, 0});
    expectVec(k.normal({0.1, 0, 0}), {0, -1, 0});
    EXPECT_TRUE(k.inside({0.7, 0.5, 0}));
    EXPECT_FALSE(k.inside({0.8, 0.5, 0}));
}

TEST(Cone, PointedConeIgnoresTheMirrorNappe) {
    Cone k({0, 0, 0}, 1, {0, 1, 0}, 0, true);
    // A horizontal ray above the apex would cross the mirrored cone.
    EXPECT_TRUE(hits(k, {{-5, 1.5, 0}, {1, 0, 0}}).empty());
    auto ts = hits(k, {{-5, 0.5, 0}, {1, 0, 0}});
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_DOUBLE_EQ(ts[0], 4.5);
    EXPECT_DOUBLE_EQ(ts[1], 5.5);
    const Bounds b = k.bounds();
    expectVec(b.lo, {-1, 0, -1});
    expectVec(b.hi, {1, 1, 1});
}

TEST(Disc, RingHitsAndHalfSpaceInside) {
    Disc d({0, 1, 0}, {0, 2, 0}, 2, 0.5);
    double t;
    ASSERT_TRUE(d.firstHit({{1, 5, 0}, {0, -1, 0}}, 0, kInfinity, t));
    EXPECT_DOUBLE_EQ(t, 4);
    EXPECT_FALSE(d.firstHit({{0.2, 5, 0}, {0, -1, 0}}, 0, kInfinity, t));  // in the hole
    EXPECT_FALSE(d.firstHit({{2.5, 5, 0}, {0, -1, 0}}, 0, kInfinity, t));  // beyond the rim
    expectVec(d.normal({1, 1, 0}), {0, 1, 0});
    // povray: the inside is the half-space behind the normal, any radius.
    EXPECT_TRUE(d.inside({10, 0.5, 0}));
    EXPECT_FALSE(d.inside({0, 1.5, 0}));
    EXPECT_FALSE(d.insideBounds().isFinite());
    // povray's disc bounding box is 0.001 thick each side.
    expectVec(d.bounds().lo, {-2, 0.999, -2});
    expectVec(d.bounds().hi, {2, 1.001, 2});
}

TEST(Triangle, HitsEdgesAndPatchRules) {
    Triangle tri({0, 0, 0}, {2, 0, 0}, {0, 2, 0});
    double t;
    ASSERT_TRUE(tri.firstHit({{0.5, 0.5, -3}, {0, 0, 1}}, 0, kInfinity, t));
    EXPECT_DOUBLE_EQ(t, 3);
    ASSERT_TRUE(tri.firstHit({{1, 1, -3}, {0, 0, 1}}, 0, kInfinity, t));  // on the long edge
    EXPECT_FALSE(tri.firstHit({{1.1, 1.1, -3}, {0, 0, 1}}, 0, kInfinity, t));
    EXPECT_FALSE(tri.firstHit({{0.5, 0.5, -3}, {0, 0, 1}}, 3.5, kInfinity, t));
    expectVec(tri.normal({0.5, 0.5, 0}), {0, 0, 1});
    EXPECT_FALSE(tri.inside({0.5, 0.5, 0}));
    EXPECT_TRUE(tri.isPatch());
    EXPECT_TRUE(tri.insideBounds().isEmpty());
    EXPECT_FALSE(tri.isDegenerate());
    Triangle line({0, 0, 0}, {1, 0, 0}, {2, 0, 0});
    EXPECT_TRUE(line.isDegenerate());
    EXPECT_FALSE(line.firstHit({{1, 0, -1}, {0, 0, 1}}, 0, kInfinity, t));
}

TEST(SmoothTriangle, NormalsBlendByBarycentricWeights) {
    SmoothTriangle tri({0, 0, 0}, {0, 0, -1}, {1, 0, 0}, {1, 0, -1}, {0, 1, 0}, {0, 1, -1});
    // At a corner: that corner's (normalised) normal.
    expectVec(tri.normal({1, 0, 0}), normalize(Vec3{1, 0, -1}));
    expectVec(tri.normal({0, 0, 0}), {0, 0, -1});
    // Middle of the b-c edge: half of each.
    expectVec(tri.normal({0.5, 0.5, 0}),
              normalize(Vec3{0.5 / std::sqrt(2), 0.5 / std::sqrt(2), -1 / std::sqrt(2)}));
    double t;
    ASSERT_TRUE(tri.firstHit({{0.25, 0.25, 1}, {0, 0, -1}}, 0, kInfinity, t));
    EXPECT_DOUBLE_EQ(t, 1);
}

TEST(Quadric, SphereAndCylinderForms) {
    // x² + y² + z² - 4 = 0: a sphere of radius 2.
    Quadric sphere({1, 1, 1, 0, 0, 0, 0, 0, 0, -4});
    auto ts = hits(sphere, {{0, 0, -5}, {0, 0, 1}});
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_DOUBLE_EQ(ts[0], 3);
    EXPECT_DOUBLE_EQ(ts[1], 7);
    expectVec(sphere.normal({0, 2, 0}), {0, 1, 0});
    EXPECT_TRUE(sphere.inside({1, 1, 1}));
    EXPECT_FALSE(sphere.inside({2, 1, 1}));
    expectVec(sphere.bounds().lo, {-2, -2, -2});
    expectVec(sphere.bounds().hi, {2, 2, 2});
    // x² + z² - 1 with linear term: (x-1)² + z² = 1 written as x² - 2x + z² = 0.
    Quadric cyl({1, 0, 1, 0, 0, 0, -2, 0, 0, 0});
    ts = hits(cyl, {{-3, 7, 0}, {1, 0, 0}});
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_DOUBLE_EQ(ts[0], 3);
    EXPECT_DOUBLE_EQ(ts[1], 5);
    expectVec(cyl.normal({0, 7, 0}), {-1, 0, 0});
    EXPECT_FALSE(cyl.bounds().isFinite());
}

TEST(Quadric, MixedTermsAndEllipsoidBounds) {
    // x² + y² + xy = 3 (D is the xy coefficient): at y = 0, x = ±sqrt(3).
    Quadric q({1, 1, 0, 1, 0, 0, 0, 0, 0, -3});
    auto ts = hits(q, {{-5, 0, 0}, {1, 0, 0}});
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 5 - std::sqrt(3), 1e-12);
    // Gradient (2x + y, 2y + x, 0) at (sqrt3, 0, 0).
    expectVec(q.normal({std::sqrt(3), 0, 0}), normalize(Vec3{2, 1, 0}));
    // An ellipsoid x²/4 + y² + z²/9 = 1 centred at (1, 0, 0):
    // 0.25x² - 0.5x + y² + z²/9 - 0.75 = 0.
    Quadric e({0.25, 1, 1.0 / 9, 0, 0, 0, -0.5, 0, 0, -0.75});
    expectVec(e.bounds().lo, {-1, -1, -3}, 1e-9);
    expectVec(e.bounds().hi, {3, 1, 3}, 1e-9);
    // Its negation has the same surface but the outside as its inside.
    Quadric n({-0.25, -1, -1.0 / 9, 0, 0, 0, 0.5, 0, 0, 0.75});
    expectVec(n.bounds().hi, {3, 1, 3}, 1e-9);
    EXPECT_FALSE(n.insideBounds().isFinite());
    EXPECT_TRUE(n.inside({10, 0, 0}));
}

TEST(JuliaFractal, ZeroParameterIsTheUnitBall) {
    // With c = 0 the square of a quaternion inside the unit ball stays
    // inside it, and the bailout radius is 1 + |c| (+ 1e-7, as povray's):
    // the set is the ball.
    const JuliaFractal j({0, 0, 0, 0}, JuliaFractal::Algebra::Quaternion,
                         JuliaFractal::Function::Sqr, 20, 20);
    EXPECT_TRUE(j.inside(Vec3(0.5, 0.3, -0.2)));
    EXPECT_FALSE(j.inside(Vec3(1.05, 0, 0)));
    // The entry, refined to povray's 1e-7 on the inside side.
    const auto ts = hits(j, Ray{Vec3(-3, 0, 0), Vec3(1, 0, 0)});
    ASSERT_GE(ts.size(), 1u);
    EXPECT_GE(ts[0], 2);
    EXPECT_LT(ts[0], 2 + 1e-7);
    // povray marches the set out of its bounding sphere without meeting
    // the far side (measured: trace() from inside the ball finds nothing,
    // a difference of a sphere and the ball sees only the sphere).
    double t = 0;
    EXPECT_FALSE(j.firstHit(Ray{Vec3(0, 0, 0), Vec3(1, 0, 0)}, 0, kInfinity, t));
    // The bounding sphere: povray's 1 + |c| + 1e-7 (at most 2).
    EXPECT_NEAR(j.bounds().hi.x, 1.0, 2e-7);
    const JuliaFractal wide({0.9, 0.9, 0, 0}, JuliaFractal::Algebra::Quaternion,
                            JuliaFractal::Function::Sqr, 5, 20);
    EXPECT_DOUBLE_EQ(wide.bounds().hi.x, 2.0);
    // The normal: the gradient of |q(N)|^2 (= |p|^(2^(N+1)) here; few
    // iterations keep the finite differences tame).
    const JuliaFractal few({0, 0, 0, 0}, JuliaFractal::Algebra::Quaternion,
                           JuliaFractal::Function::Sqr, 3, 20);
    expectVec(few.normal(Vec3(0.6, 0.8, 0)), Vec3(0.6, 0.8, 0), 1e-5);
}

TEST(JuliaFractal, HypercomplexSquareAndQuaternionCube) {
    // Hypercomplex: the bailout radius is 4 whatever c; 0.5 squares to
    // 0.25 (+ c = 0.25 - 0.3 ...) and stays small, 3 runs away.
    const JuliaFractal h({-0.3, 0.1, 0, 0}, JuliaFractal::Algebra::Hypercomplex,
                         JuliaFractal::Function::Sqr, 10, 20);
    EXPECT_DOUBLE_EQ(h.bounds().hi.x, 4.0);
    EXPECT_TRUE(h.inside(Vec3(0.5, 0, 0)));
    EXPECT_FALSE(h.inside(Vec3(3, 0, 0)));
    // Cube with c = 0: again the unit ball (|q^3| = |q|^3).
    const JuliaFractal cube({0, 0, 0, 0}, JuliaFractal::Algebra::Quaternion,
                            JuliaFractal::Function::Cube, 8, 20);
    EXPECT_TRUE(cube.inside(Vec3(0, 0.7, 0.7)));
    EXPECT_FALSE(cube.inside(Vec3(0, 0.75, 0.75)));
}
