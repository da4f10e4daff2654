// Superellipsoid, isosurface, lathe, sor, prism and sphere_sweep: hits
// against known geometry, inside tests, normals and parsing.
#include <gtest/gtest.h>

#include <cmath>

#include "parse_support.h"
#include "scene/isosurface.h"
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
    EXPECT_NEAR(ts[0], 4, 1e-9);
    EXPECT_NEAR(ts[1], 6, 1e-9);
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
    const Ray down{{0.2, 5, 0.1}, {0, -1, 0}};
    auto ts = hitsOf(closed, down);
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 5, 1e-9);
    EXPECT_NEAR(ts[1], 6, 1e-12);
    EXPECT_NEAR(closed.normal(down.at(ts[1])).y, -1, 1e-12);
    s.open = true;
    const Isosurface open(s);
    ts = hitsOf(open, down);
    ASSERT_EQ(ts.size(), 1u);
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

TEST(SweepShapesParse, Errors) {
    EXPECT_NE(parseErrorOf("superellipsoid { <0, 1> }").find("Illegal superellipsoid"),
              std::string::npos);
    EXPECT_NE(parseErrorOf("isosurface { function { internal(61) } }").find("not supported yet"),
              std::string::npos);
    EXPECT_NE(parseErrorOf("#declare G = function { internal(61) }\n"
                           "isosurface { function { G(x, y, z, 1) } }")
                  .find("not supported yet"),
              std::string::npos);
    EXPECT_NE(parseErrorOf("isosurface { function { x } contained_by { cone { 0, 1, y, 0 } } }"),
              "");
}

}  // namespace
}  // namespace frameray::scene
