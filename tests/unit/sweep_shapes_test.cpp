// Superellipsoid, isosurface, parametric, lathe, sor, prism and sphere_sweep: hits
// against known geometry, inside tests, normals and parsing.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "parse_support.h"
#include "render/renderer.h"
#include "render/world.h"
#include "scene/isosurface.h"
#include "scene/parametric.h"
#include "scene/prism.h"
#include "scene/sphere_sweep.h"
#include "scene/spline_revolution.h"
#include "scene/superellipsoid.h"
#include "sdl/function_value.h"

namespace frameray::scene {
namespace {

using test_support::ParsedScene;
using test_support::parseErrorOf;

std::vector<double> hitsOf(const Shape& s, const Ray& r, double tMin = 1e-9,
                           double tMax = kInfinity) {
    std::vector<double> ts;
    s.allHits(r, tMin, tMax, ts);
    return ts;
}

TEST(Superellipsoid, UnitExponentsMakeTheUnitSphere) {
    const Superellipsoid s(1, 1);
    const Ray r{{0.3, -0.2, -5}, {0, 0, 1}};
    const auto ts = hitsOf(s, r);
    ASSERT_EQ(ts.size(), 2u);
    const double half = std::sqrt(1 - 0.09 - 0.04);
    EXPECT_NEAR(ts[0], 5 - half, 1e-10);
    EXPECT_NEAR(ts[1], 5 + half, 1e-10);
    const Vec3 n = s.normal(r.at(ts[0]));
    EXPECT_NEAR(n.x, 0.3, 1e-9);
    EXPECT_NEAR(n.z, -half, 1e-9);
    EXPECT_TRUE(s.inside({0.5, 0.5, 0.5}));
    EXPECT_FALSE(s.inside({0.6, 0.6, 0.6}));
}

TEST(Superellipsoid, SmallExponentsApproachTheCube) {
    const Superellipsoid s(0.05, 0.05);
    const Ray r{{0.5, 0.5, -3}, {0, 0, 2}};
    const auto ts = hitsOf(s, r);
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(r.at(ts[0]).z, -1, 1e-3);
    EXPECT_NEAR(r.at(ts[1]).z, 1, 1e-3);
    const Vec3 n = s.normal(r.at(ts[0]));
    EXPECT_NEAR(n.z, -1, 1e-6);
    EXPECT_TRUE(s.inside({0.95, -0.95, 0.9}));
}

TEST(Superellipsoid, PinchedShapeHasNoNanNormals) {
    const Superellipsoid s(3, 3);
    for (const Vec3 p : {Vec3(1, 0, 0), Vec3(0, 0, 1), Vec3(0, 1e-300, 0), Vec3(0.3, 0, 0.2)}) {
        const Vec3 n = s.normal(p);
        EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
        EXPECT_NEAR(length(n), 1, 1e-12);
    }
}

IsosurfaceSettings sphereFunction(ParsedScene& p) {
    const auto* fn = std::get_if<sdl::FunctionPtr>(p.interp.lookup("F"));
    EXPECT_NE(fn, nullptr);
    IsosurfaceSettings s;
    s.function = (*fn)->compiled;
    s.boxLo = Vec3(-2);
    s.boxHi = Vec3(2);
    s.maxGradient = 5;
    return s;
}

TEST(Isosurface, FindsTheSphereOfItsFunction) {
    ParsedScene p("#declare F = function { x*x + y*y + z*z - 1 }");
    IsosurfaceSettings s = sphereFunction(p);
    s.maxTrace = 4;
    const Isosurface iso(s);
    const Ray r{{0, 0, -5}, {0, 0, 1}};
    const auto ts = hitsOf(iso, r);
    ASSERT_EQ(ts.size(), 2u);
    // povray's hit is the far end of the last interval shorter than
    // `accuracy` (0.001): past the root, by less than the accuracy.
    EXPECT_GE(ts[0], 4);
    EXPECT_LT(ts[0], 4 + s.accuracy);
    EXPECT_GE(ts[1], 6);
    EXPECT_LT(ts[1], 6 + s.accuracy);
    const Vec3 n = iso.normal(r.at(ts[0]));
    EXPECT_NEAR(n.z, -1, 1e-6);
    EXPECT_TRUE(iso.inside({0.5, 0, 0}));
    EXPECT_FALSE(iso.inside({1.5, 0, 0}));
}

TEST(Isosurface, MaxTraceOneReportsOnlyTheFirstCrossing) {
    ParsedScene p("#declare F = function { x*x + y*y + z*z - 1 }");
    const Isosurface iso(sphereFunction(p));
    EXPECT_EQ(hitsOf(iso, {{0, 0, -5}, {0, 0, 1}}).size(), 1u);
}

TEST(Isosurface, ClosedContainerCapsTheInside) {
    // Everything below y = 0 is inside; the box closes it at its faces.
    ParsedScene p("#declare F = function { y }");
    IsosurfaceSettings s = sphereFunction(p);
    s.maxTrace = 4;
    s.boxLo = Vec3(-1);
    s.boxHi = Vec3(1);
    const Isosurface closed(s);
    // As in povray 3.7: a ray from outside the container meets the face
    // where it enters (where the function is inside there) and the
    // function's crossings, not the face where it leaves.
    const Ray down{{0.2, 5, 0.1}, {0, -1, 0}};
    auto ts = hitsOf(closed, down);
    ASSERT_EQ(ts.size(), 1u);
    EXPECT_GE(ts[0], 5);
    EXPECT_LT(ts[0], 5 + s.accuracy);
    const Ray up{{0.2, -5, 0.1}, {0, 1, 0}};
    ts = hitsOf(closed, up);
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 4, 1e-12);
    EXPECT_NEAR(closed.normal(up.at(ts[0])).y, -1, 1e-12);
    EXPECT_GE(ts[1], 5);
    EXPECT_LT(ts[1], 5 + s.accuracy);
    // A ray from inside meets the face where it leaves.
    const Ray fromInside{{0.2, -0.5, 0.1}, {0, -1, 0}};
    ts = hitsOf(closed, fromInside);
    ASSERT_EQ(ts.size(), 1u);
    EXPECT_NEAR(ts[0], 0.5, 1e-12);
    EXPECT_NEAR(closed.normal(fromInside.at(ts[0])).y, -1, 1e-12);
    s.open = true;
    const Isosurface open(s);
    ts = hitsOf(open, down);
    ASSERT_EQ(ts.size(), 1u);
    EXPECT_TRUE(hitsOf(open, fromInside).empty());
}

TEST(Isosurface, RayFromTheSurfaceDoesNotHitItself) {
    ParsedScene p("#declare F = function { x*x + y*y + z*z - 1 }");
    const Isosurface iso(sphereFunction(p));
    const Ray r{{0, 0, -5}, {0, 0.01, 1}};
    const auto ts = hitsOf(iso, r);
    ASSERT_EQ(ts.size(), 1u);
    const Vec3 hit = r.at(ts[0]);
    // Leaving at a grazing angle and leaving straight out.
    EXPECT_TRUE(hitsOf(iso, {hit, {1, 0.3, 0}}).empty());
    EXPECT_TRUE(hitsOf(iso, {hit, hit}).empty());
}

// The unit sphere as x = cos u sin v, y = cos v, z = sin u sin v.
ParametricSettings parametricSphere(ParsedScene& p) {
    auto fn = [&](const char* name) {
        const auto* f = std::get_if<sdl::FunctionPtr>(p.interp.lookup(name));
        EXPECT_NE(f, nullptr);
        return (*f)->compiled;
    };
    ParametricSettings s;
    s.fx = fn("FX");
    s.fy = fn("FY");
    s.fz = fn("FZ");
    s.uMax = 2 * M_PI;
    s.vMax = M_PI;
    s.sphereContainer = true;
    s.radius = 1.01;
    return s;
}

const char* kSphereFunctions =
    "#declare FX = function { cos(u)*sin(v) }\n"
    "#declare FY = function { cos(v) }\n"
    "#declare FZ = function { sin(u)*sin(v) }\n";

// povray's rule (see parametric.h) reports the ray's entry into the last
// piece's z slab: a little in front of the surface, never behind it; the
// exact values are checked against povray in language.parametric_trace.
TEST(Parametric, FindsTheFirstCrossingOfTheSphereJustInFront) {
    ParsedScene p(kSphereFunctions);
    const Parametric sphere(parametricSphere(p));
    const Ray r{{0.3, -0.2, -5}, {0, 0, 1}};
    const auto ts = hitsOf(sphere, r);
    // Only the first crossing, as povray reports.
    ASSERT_EQ(ts.size(), 1u);
    const double half = std::sqrt(1 - 0.09 - 0.04);
    EXPECT_LE(ts[0], 5 - half + 1e-12);
    EXPECT_GE(ts[0], 5 - half - 0.01);
    const Vec3 n = sphere.normal(r.at(ts[0]));
    EXPECT_NEAR(std::fabs(n.x), 0.3, 0.01);
    EXPECT_NEAR(std::fabs(n.z), half, 0.01);
    // Near a pole, where d/du vanishes: still a unit, finite normal.
    const Vec3 pole = sphere.normal({0, 1, 0});
    EXPECT_NEAR(std::fabs(pole.y), 1, 1e-4);
    // From inside the sphere: the far wall.
    const auto inner = hitsOf(sphere, {{0, 0, 0}, {1, 0, 0}});
    ASSERT_EQ(inner.size(), 1u);
    EXPECT_NEAR(inner[0], 1, 0.01);
    EXPECT_LE(inner[0], 1 + 1e-12);
    // It encloses nothing.
    EXPECT_FALSE(sphere.inside({0, 0, 0}));
    EXPECT_TRUE(sphere.isPatch());
    EXPECT_FALSE(sphere.warnsAsPatch());
}

TEST(Parametric, RayFromTheSurfaceDoesNotHitItself) {
    ParsedScene p(kSphereFunctions);
    const Parametric sphere(parametricSphere(p));
    const Ray r{{0.2, 0.1, -5}, {0, 0, 1}};
    const auto ts = hitsOf(sphere, r);
    ASSERT_EQ(ts.size(), 1u);
    const Vec3 hit = r.at(ts[0]);
    EXPECT_TRUE(hitsOf(sphere, {hit, hit}).empty());
}

TEST(Parametric, UnderestimatedMaxGradientStillFindsTheSurface) {
    // x = 4u: gradient 4 against max_gradient 0.01 (povray renders it).
    ParsedScene p(
        "#declare FX = function { 4*u }\n#declare FY = function { 0.2*sin(8*u)*v }\n"
        "#declare FZ = function { 4*v }\n");
    ParametricSettings s = parametricSphere(p);
    s.uMin = s.vMin = -0.3;
    s.uMax = s.vMax = 0.3;
    s.sphereContainer = false;
    s.boxLo = Vec3(-2);
    s.boxHi = Vec3(2);
    s.maxGradient = 0.01;
    const Parametric sheet(s);
    int found = 0;
    for (double x = -1.1; x <= 1.1; x += 0.1) {
        const auto ts = hitsOf(sheet, {{x, 3, 0.37}, {0, -1, 0}});
        if (ts.size() != 1) continue;
        ++found;
        const double u = x / 4, v = 0.37 / 4;
        // Within a couple of accuracies (0.001) of the sheet, as in povray.
        EXPECT_NEAR(3 - ts[0], 0.2 * std::sin(8 * u) * v, 0.002);
    }
    EXPECT_EQ(found, 23);
}

TEST(SweepShapesParse, Parametric) {
    ParsedScene p(
        "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1>\n"
        "  contained_by { box { <-1, -1, -1>, <2, 2, 1> } } max_gradient 2 accuracy 0.0001\n"
        "  precompute 10 x, z }\n"
        "intersection { box { -1, 1 } parametric { function { u } function { v } function { 0 }\n"
        "  <0, 0>, <1, 1> precompute 5, x, y, z } }\n");
    ASSERT_EQ(p.scene.objects.size(), 2u);
    EXPECT_STREQ(p.scene.objects[0]->shape->name(), "parametric");
    EXPECT_DOUBLE_EQ(p.scene.objects[0]->shape->bounds().hi.x, 2);
    // povray gives no "Patch objects" warning for a parametric.
    EXPECT_EQ(p.sink.warnings.find("Patch objects"), std::string::npos);
    EXPECT_NE(parseErrorOf("parametric { function { u } function { v } <0, 0>, <1, 1> }"), "");
    EXPECT_NE(parseErrorOf("parametric { function { u } function { v } function { 0 } <0, 0>, "
                           "<1, 1> precompute 21 x }")
                  .find("invalid depth"),
              std::string::npos);
}

TEST(BlobTextures, ComponentTexturesAreBlendedByFieldShare) {
    ParsedScene p(
        "blob { threshold 0.5\n"
        "  sphere { <-0.5, 0, 0>, 1, 1 pigment { rgb <1, 0, 0> } }\n"
        "  sphere { <0.5, 0, 0>, 1, 1 }\n"
        "  sphere { <0, 0, 0.5>, 1, -1 pigment { rgb <0, 0, 1> } translate x }\n"
        "  pigment { rgb <0, 1, 0> } }\n");
    ASSERT_EQ(p.scene.objects.size(), 1u);
    const Object& obj = *p.scene.objects[0];
    ASSERT_EQ(obj.componentTextures.size(), 3u);
    EXPECT_NE(obj.componentTextures[0], nullptr);
    EXPECT_EQ(obj.componentTextures[1], nullptr);
    // At the origin both positive components add 0.5625; the negative one
    // (moved to <1, 0, 0.5>, d^2 = 1.25) adds nothing.
    RGB sum(0.0);
    double weights = 0;
    obj.visitTextures({0, 0, 0}, *obj.texture, [&](const Texture& t, double w) {
        sum += t.pigment->at({0, 0, 0}).rgb * w;
        weights += w;
    });
    EXPECT_NEAR(weights, 1, 1e-12);
    EXPECT_NEAR(sum.r, 0.5, 1e-12);
    EXPECT_NEAR(sum.g, 0.5, 1e-12);
    EXPECT_NEAR(sum.b, 0, 1e-12);
    // Near the negative component its share counts by magnitude.
    sum = RGB(0.0);
    obj.visitTextures({0.6, 0, 0.3}, *obj.texture, [&](const Texture& t, double w) {
        sum += t.pigment->at({0, 0, 0}).rgb * w;
    });
    EXPECT_GT(sum.b, 0.01);
}

TEST(Lathe, LinearProfileIsACylinderWall) {
    // From (1, 0) up to (1, 2): the side of a cylinder of radius 1.
    const Lathe lathe(SplineKind::Linear, {{1, 0}, {1, 2}});
    const Ray r{{0.5, 1, -5}, {0, 0, 1}};
    const auto ts = hitsOf(lathe, r);
    ASSERT_EQ(ts.size(), 2u);
    const double half = std::sqrt(1 - 0.25);
    EXPECT_NEAR(ts[0], 5 - half, 1e-10);
    EXPECT_NEAR(ts[1], 5 + half, 1e-10);
    const Vec3 n = lathe.normal(r.at(ts[0]));
    EXPECT_NEAR(n.x, 0.5, 1e-9);
    EXPECT_NEAR(n.y, 0, 1e-9);
    // Rays along and near the horizontal, and one up the axis.
    EXPECT_EQ(hitsOf(lathe, {{-5, 1.5, 0}, {1, 0, 0}}).size(), 2u);
    EXPECT_EQ(hitsOf(lathe, {{-5, 1.5, 0}, {1, 1e-9, 0}}).size(), 2u);
    EXPECT_TRUE(hitsOf(lathe, {{0, -5, 0}, {0, 1, 0}}).empty());
}

TEST(Lathe, ClosedProfileInsideAndBezierPieces) {
    // A closed triangle profile: a cone-like solid.
    const Lathe cone(SplineKind::Linear, {{0, 0}, {1, 0}, {0, 1}, {0, 0}});
    EXPECT_TRUE(cone.inside({0.2, 0.2, 0.1}));
    EXPECT_FALSE(cone.inside({0.6, 0.6, 0}));
    const Bounds b = cone.bounds();
    EXPECT_DOUBLE_EQ(b.hi.x, 1);
    EXPECT_DOUBLE_EQ(b.hi.y, 1);
    // A bezier quarter of a circle-ish dome: the ray down the axis meets
    // its top where the profile reaches the axis with a flat tangent.
    const Lathe dome(SplineKind::Bezier, {{1, 0}, {1, 0.55}, {0.55, 1}, {0, 1}});
    const auto ts = hitsOf(dome, {{0, 5, 0}, {0, -1, 0}});
    ASSERT_FALSE(ts.empty());
    EXPECT_NEAR(ts[0], 4, 1e-9);
    const Vec3 n = dome.normal({0, 1, 0});
    EXPECT_NEAR(std::fabs(n.y), 1, 1e-12);
    EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.z));
}

TEST(Lathe, NormalAndUvFromTheNearestPieceAsAFullSearch) {
    // normal() and uv() skip pieces whose box lies farther than the
    // nearest piece found; they must pick what measuring every piece in
    // order (the first of equally near ones) picks, bit for bit.
    const std::vector<ProfilePoint> points{{2, 1},    {2, -1},     {3, -1},  {3.4, -2},
                                           {4, -1.1}, {3.6, -0.9}, {2.6, 0}, {3.6, 0.9},
                                           {4, 1.1},  {3.4, 2},    {3, 1},   {2, 1}};
    for (const SplineKind kind : {SplineKind::Linear, SplineKind::Cubic}) {
        const Lathe lathe(kind, points);
        std::vector<ProfileSegment> pieces;
        const int per = pointsPerSegment(kind);
        for (size_t i = 0; i + static_cast<size_t>(per) <= points.size(); ++i)
            pieces.push_back(makeProfileSegment(kind, &points[i]));
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> angle(0, 6.283), radius(1.5, 4.5), height(-2.5, 2.5);
        int onSurface = 0;
        for (int n = 0; n < 3000; ++n) {
            // Half the points on the profile (the pieces' joints included),
            // half anywhere around it.
            double rho = radius(rng), y = height(rng);
            if (n % 2 == 0) {
                const auto& piece = pieces[static_cast<size_t>(n / 2) % pieces.size()];
                const ProfilePoint at = piece.at((n / 2 / pieces.size()) % 5 / 4.0);
                rho = at.u, y = at.v;
                ++onSurface;
            }
            const double a = angle(rng);
            const Vec3 p{rho * std::cos(a), y, rho * std::sin(a)};
            double best = kInfinity, bestS = 0;
            size_t bestIndex = 0;
            for (size_t i = 0; i < pieces.size(); ++i) {
                double s;
                const double d =
                    closestOnSegment(pieces[i], std::sqrt(p.x * p.x + p.z * p.z), p.y, s);
                if (d < best) best = d, bestS = s, bestIndex = i;
            }
            double u, v;
            ASSERT_TRUE(lathe.uv(p, u, v));
            EXPECT_EQ(v, (static_cast<double>(bestIndex) + bestS) / pieces.size()) << n;
            const ProfilePoint tan = pieces[bestIndex].tangent(bestS);
            if (tan.u == 0 && tan.v == 0) continue;
            const double r = std::sqrt(p.x * p.x + p.z * p.z);
            const Vec3 expected = normalize(Vec3{tan.v * p.x / r, -tan.u, tan.v * p.z / r});
            const Vec3 got = lathe.normal(p);
            EXPECT_EQ(got.x, expected.x) << n;
            EXPECT_EQ(got.y, expected.y) << n;
            EXPECT_EQ(got.z, expected.z) << n;
        }
        EXPECT_GT(onSurface, 1000);
    }
}

TEST(Sor, ConstantRadiusIsACappedCylinder) {
    const Sor sor({{1, -1}, {1, 0}, {1, 1}, {1, 2}}, false);
    const auto ts = hitsOf(sor, {{0.3, 5, 0}, {0, -1, 0}});
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 4, 1e-12);
    EXPECT_NEAR(ts[1], 5, 1e-12);
    EXPECT_NEAR(sor.normal({0.3, 1, 0}).y, 1, 1e-12);
    const auto side = hitsOf(sor, {{-5, 0.5, 0}, {1, 0, 0}});
    ASSERT_EQ(side.size(), 2u);
    EXPECT_NEAR(side[0], 4, 1e-12);
    EXPECT_NEAR(sor.normal({-1, 0.5, 0}).x, -1, 1e-12);
    EXPECT_TRUE(sor.inside({0.5, 0.5, 0.5}));
    EXPECT_FALSE(sor.inside({0.5, 1.5, 0}));
    const Sor open({{1, -1}, {1, 0}, {1, 1}, {1, 2}}, true);
    EXPECT_TRUE(hitsOf(open, {{0.3, 5, 0}, {0, -1, 0}}).empty());
}

TEST(Prism, SquareWithHole) {
    bool unclosed = true;
    const auto outline = Prism::outlineOf(SplineKind::Linear,
                                          {{-1, -1},
                                           {1, -1},
                                           {1, 1},
                                           {-1, 1},
                                           {-1, -1},
                                           {-0.5, -0.5},
                                           {0.5, -0.5},
                                           {0.5, 0.5},
                                           {-0.5, 0.5},
                                           {-0.5, -0.5}},
                                          unclosed);
    EXPECT_FALSE(unclosed);
    EXPECT_EQ(outline.size(), 8u);
    const Prism prism(outline, 0, 1, false, false);
    EXPECT_TRUE(prism.inside({0.75, 0.5, 0}));
    EXPECT_FALSE(prism.inside({0, 0.5, 0}));
    // Down through the frame, and through the hole.
    auto ts = hitsOf(prism, {{0.75, 5, 0.1}, {0, -1, 0}});
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 4, 1e-12);
    EXPECT_NEAR(prism.normal({0.75, 1, 0.1}).y, 1, 1e-12);
    EXPECT_TRUE(hitsOf(prism, {{0, 5, 0}, {0, -1, 0}}).empty());
    // Across: wall, hole, wall.
    ts = hitsOf(prism, {{-5, 0.5, 0}, {1, 0, 0}});
    ASSERT_EQ(ts.size(), 4u);
    EXPECT_NEAR(ts[1], 4.5, 1e-12);
    EXPECT_NEAR(std::fabs(prism.normal({-0.5, 0.5, 0}).x), 1, 1e-9);  // normals face either way
}

TEST(Prism, ConicSweepScalesWithHeight) {
    bool unclosed;
    const auto outline = Prism::outlineOf(SplineKind::Linear,
                                          {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}}, unclosed);
    const Prism prism(outline, 0.5, 1, true, false);
    // At y = 0.75 the square reaches 0.75.
    const auto ts = hitsOf(prism, {{-5, 0.75, 0}, {1, 0, 0}});
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 5 - 0.75, 1e-12);
    const Vec3 n = prism.normal({-0.75, 0.75, 0});
    EXPECT_NEAR(n.x * n.y, 0.5, 1e-9);  // the wall x = -y: along (1, 1, 0) or its opposite
    EXPECT_NEAR(n.z, 0, 1e-9);
    EXPECT_TRUE(prism.inside({0.6, 0.75, 0.6}));
    EXPECT_FALSE(prism.inside({0.6, 0.55, 0}));
}

TEST(SphereSweep, LinearSweepIsBallsAndTangentCone) {
    const SphereSweep sweep(SweepSpline::Linear, {{{0, 0, 0}, 1}, {{4, 0, 0}, 0.5}});
    // Through the big ball's centre across the axis, and along the axis.
    auto ts = hitsOf(sweep, {{0, 5, 0}, {0, -1, 0}});
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 4, 1e-12);
    ts = hitsOf(sweep, {{-5, 0, 0}, {1, 0, 0}});
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 4, 1e-12);
    EXPECT_NEAR(ts[1], 9.5, 1e-12);
    EXPECT_TRUE(sweep.inside({2, 0.5, 0}));
    EXPECT_FALSE(sweep.inside({2, 0.9, 0}));
    EXPECT_NEAR(sweep.normal({4.5, 0, 0}).x, 1, 1e-9);
    // Over the small ball's centre the cone (slope k = -1/8) is the surface.
    const Vec3 n = sweep.normal(
        {4, 0.5 / std::sqrt(1 - 1.0 / 64) + 0.0625 * 0.125 / std::sqrt(1 - 1.0 / 64), 0});
    EXPECT_NEAR(n.x, 0.125, 1e-6);
}

TEST(SweepShapesParse, SuperellipsoidAndIsosurface) {
    ParsedScene p(
        "superellipsoid { <0.5, 2> }\n"
        "isosurface { function { x*x + y*y - 0.5 } contained_by { sphere { 0, 2 } } threshold 0.1 "
        "accuracy 0.01 max_gradient 3 open max_trace 2 }\n"
        "isosurface { function { x } all_intersections evaluate 2, 1.2, 0.9 }\n");
    ASSERT_EQ(p.scene.objects.size(), 3u);
    EXPECT_STREQ(p.scene.objects[0]->shape->name(), "superellipsoid");
    EXPECT_STREQ(p.scene.objects[1]->shape->name(), "isosurface");
    const Bounds b = p.scene.objects[1]->shape->bounds();
    EXPECT_DOUBLE_EQ(b.hi.x, 2);
}

TEST(SweepShapesParse, LatheSorPrismSphereSweep) {
    ParsedScene p(
        "lathe { 3, <0, 0>, <1, 1>, <0, 2> sturm }\n"
        "lathe { bezier_spline 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }\n"
        "sor { 4, <1, 0>, <1, 1>, <1, 2>, <1, 3> open }\n"
        "prism { conic_sweep cubic_spline 0.5, 1, 6, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0>, <1, "
        "0> }\n"
        "sphere_sweep { b_spline 4, <0, 0, 0>, 1, <1, 0, 0>, 1, <2, 1, 0>, 1, <3, 0, 0>, 1 "
        "tolerance 0.001 }\n");
    ASSERT_EQ(p.scene.objects.size(), 5u);
    EXPECT_STREQ(p.scene.objects[2]->shape->name(), "sor");
    EXPECT_STREQ(p.scene.objects[3]->shape->name(), "prism");
    EXPECT_STREQ(p.scene.objects[4]->shape->name(), "sphere_sweep");
    ParsedScene unclosed("prism { 0, 1, 3, <0, 0>, <1, 0>, <1, 1> }");
    EXPECT_NE(unclosed.sink.warnings.find("Prism not closed"), std::string::npos);
}

TEST(SweepShapesParse, Errors) {
    EXPECT_NE(parseErrorOf("lathe { bezier_spline 5, <0,0>, <1,0>, <1,1>, <0,1>, <0,2> }"), "");
    EXPECT_NE(parseErrorOf("lathe { cubic_spline 3, <0,0>, <1,0>, <1,1> }"), "");
    EXPECT_NE(parseErrorOf("sor { 4, <1, 0>, <1, 1>, <1, 1>, <1, 3> }").find("Incorrect point"),
              std::string::npos);
    EXPECT_NE(parseErrorOf("sphere_sweep { b_spline 3, <0,0,0>, 1, <1,0,0>, 1, <2,0,0>, 1 }"), "");
    EXPECT_NE(parseErrorOf("superellipsoid { <0, 1> }").find("Illegal superellipsoid"),
              std::string::npos);
    // internal(78) is f_noise_generator: generator 3 (Perlin) is accepted.
    EXPECT_EQ(parseErrorOf("#declare G = function { internal(78) }\n"
                           "isosurface { function { G(x, y, z, 3) } }"),
              "");
    // internal(40) is f_mesh1: a thread distance <= 0 is not matched yet.
    EXPECT_NE(parseErrorOf("#declare G = function { internal(40) }\n"
                           "isosurface { function { G(x, y, z, 0, 1, 1, 0.1, 1) } }")
                  .find("not supported yet"),
              std::string::npos);
    // internal(24) is f_helical_torus: ten parameters after x, y, z.
    EXPECT_NE(parseErrorOf("isosurface { function { internal(24) } }").find("takes 13 parameters"),
              std::string::npos);
    EXPECT_EQ(parseErrorOf("#declare G = function { internal(24) }\n"
                           "isosurface { function { G(x, y, z, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10) } }"),
              "");
    // f_sphere takes a radius after x, y, z: an isosurface body cannot be it.
    EXPECT_NE(parseErrorOf("isosurface { function { internal(61) } }").find("takes 4 parameters"),
              std::string::npos);
    EXPECT_EQ(parseErrorOf("#declare G = function { internal(61) }\n"
                           "isosurface { function { G(x, y, z, 1) } }"),
              "");
    EXPECT_NE(parseErrorOf("isosurface { function { x } contained_by { cone { 0, 1, y, 0 } } }"),
              "");
}

// The stability scenes (tests/stability/sweep_*.pov) at three scales:
// every pixel of the linear image is a finite number.
TEST(SweepStability, NoNanPixels) {
    for (const char* name : {"sweep_lathe_axis", "sweep_isosurface_steep"}) {
        for (const char* scale : {"1", "1e-4", "1e5"}) {
            sdl::FrameContext ctx;
            ctx.declares = {{"S", scale}};
            ctx.imageWidth = 80;
            ctx.imageHeight = 60;
            sdl::TokenCache cache;
            test_support::WarningSink sink;
            sdl::Interpreter interp(ctx, cache, sink);
            const Scene scene = interp.parseFile(std::string(FRAMERAY_SOURCE_DIR) +
                                                 "/tests/stability/" + name + ".pov");
            render::World world(scene);
            render::FrameStats stats;
            render::FrameSettings settings;
            settings.width = 80;
            settings.height = 60;
            const auto image = render::renderFrame(world, settings, stats);
            size_t bad = 0;
            for (const float v : image.rgb)
                if (!std::isfinite(v)) ++bad;
            EXPECT_EQ(bad, 0u) << name << " at S = " << scale;
        }
    }
}

}  // namespace
}  // namespace frameray::scene
