// Light sources: the spotlight and cylinder falloff curves and the area
// light grid weights, against values measured from povray 3.7 renders.
#include "scene/lights.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "render/lighting.h"

using namespace frameray;

namespace {

// A spotlight 10 units in front of the plane z = 0, aimed at the origin.
scene::Light spotAt(double radius, double falloff, double tightness) {
    scene::Light l;
    l.kind = scene::LightKind::Spot;
    l.position = {0, 0, -10};
    l.pointAt = {0, 0, 0};
    l.radius = radius;
    l.falloff = falloff;
    l.tightness = tightness;
    return l;
}

// The point of the plane z = 0 seen from the light at `degrees` off axis.
Vec3 offAxis(double degrees) {
    return {10 * std::tan(degrees * std::numbers::pi / 180), 0, 0};
}

}  // namespace

TEST(Lights, SmoothEdgeIsPovraysCubic) {
    EXPECT_EQ(scene::smoothEdge(0.2, 0.6, 0.1), 0.0);
    EXPECT_EQ(scene::smoothEdge(0.2, 0.6, 0.7), 1.0);
    EXPECT_DOUBLE_EQ(scene::smoothEdge(0.2, 0.6, 0.4), 0.5);
    EXPECT_DOUBLE_EQ(scene::smoothEdge(0.0, 1.0, 0.25), (3 - 0.5) * 0.0625);
}

TEST(Lights, SpotlightFalloffMatchesPovray) {
    // Measured (16-bit linear renders of a plane under the spot, divided
    // by the cosine of incidence): radius 10, falloff 30.
    const struct {
        double tightness, x,
            expected;  // x: the point <x, 0, 0> (a pixel centre of the measurement)
    } cases[] = {
        {0, 1.65, 1.0},      {0, 2.45, 0.96402},  {0, 4.05, 0.51835},
        {0, 5.65, 0.00442},  {0, 6.45, 0.0},      {10, 0.05, 0.99988},
        {10, 0.85, 0.96465}, {10, 3.25, 0.48631}, {10, 4.85, 0.06821},
    };
    for (const auto& c : cases) {
        const scene::Light l = spotAt(10, 30, c.tightness);
        const Vec3 p{c.x, 0, 0};
        EXPECT_NEAR(l.attenuation(p, length(p - l.position)), c.expected, 2e-5)
            << "tightness " << c.tightness << " at x = " << c.x;
    }
    // povray's defaults: radius 30, falloff 45, tightness 0.
    scene::Light d;
    d.kind = scene::LightKind::Spot;
    d.position = {0, 0, -10};
    d.pointAt = {0, 0, 0};
    EXPECT_NEAR(d.attenuation({7.05, 0, 0}, 10), 0.77568, 2e-5);
    EXPECT_EQ(d.attenuation(offAxis(45.5), 10), 0.0);
}

TEST(Lights, CylinderFalloffMatchesPovray) {
    scene::Light l;
    l.kind = scene::LightKind::Cylinder;
    l.position = {0, 0, -10};
    l.pointAt = {0, 0, 0};
    l.radius = 3;
    l.falloff = 8;
    EXPECT_NEAR(l.attenuation({1, 0, 0}, 10), 1.0, 1e-9);
    EXPECT_NEAR(l.attenuation({3.25, 0, 0}, 10), 0.99275, 1e-4);
    EXPECT_EQ(l.attenuation({8.5, 0, 0}, 10), 0.0);
    EXPECT_EQ(l.attenuation({0, 0, -11}, 1), 0.0);  // behind the light
    l.tightness = 2;
    EXPECT_NEAR(l.attenuation({0.05, 0, 0}, 10), 0.98754, 1e-4);
    EXPECT_NEAR(l.attenuation({3.25, 0, 0}, 10), 0.35, 1e-3);
}

TEST(Lights, FadeHalvesAtTheFadeDistanceScale) {
    scene::Light l;
    l.fadeDistance = 2;
    l.fadePower = 2;
    EXPECT_DOUBLE_EQ(l.attenuation({0, 0, 0}, 2), 1.0);
    EXPECT_DOUBLE_EQ(l.attenuation({0, 0, 0}, 4), 2.0 / 5.0);
    l.fadePower = 0;  // no fading without a power
    EXPECT_DOUBLE_EQ(l.attenuation({0, 0, 0}, 4), 1.0);
}

namespace {

// Weight of every point of an n x 1 grid when everything is sampled.
std::vector<double> rowWeights(int n) {
    std::vector<double> w(n);
    for (int k = 0; k < n; ++k) {
        const RGB mean =
            render::subdivideAreaGrid(n, 1, scene::AreaLight::kSampleEveryPoint,
                                      [&](int i, int) { return RGB(i == k ? 1.0 : 0.0); });
        w[k] = mean.r;
    }
    return w;
}

}  // namespace

TEST(Lights, AreaGridWeightsMatchPovray) {
    // Measured with a pinhole under the light: each grid point lights its
    // own spot on the floor, as bright as its weight.
    auto expectRow = [](int n, std::vector<double> expected) {
        const std::vector<double> w = rowWeights(n);
        for (int k = 0; k < n; ++k)
            EXPECT_DOUBLE_EQ(w[k], expected[k]) << n << " points, point " << k;
    };
    expectRow(3, {0.25, 0.5, 0.25});
    expectRow(4, {0.25, 0.25, 0.25, 0.25});
    expectRow(5, {0.125, 0.25, 0.25, 0.25, 0.125});
    expectRow(6, {0.125, 0.25, 0.125, 0.125, 0.25, 0.125});
    expectRow(7, {0.125, 0.125, 0.125, 0.25, 0.125, 0.125, 0.125});
    expectRow(10, {0.0625, 0.125, 0.125, 0.125, 0.0625, 0.0625, 0.125, 0.125, 0.125, 0.0625});
}

TEST(Lights, AdaptiveGridStopsWhenCornersAgree) {
    int calls = 0;
    const RGB lit = render::subdivideAreaGrid(9, 9, 0, [&](int, int) {
        ++calls;
        return RGB(1.0);
    });
    EXPECT_EQ(calls, 4);  // the corners only
    EXPECT_DOUBLE_EQ(lit.r, 1.0);
    calls = 0;
    render::subdivideAreaGrid(9, 9, 1, [&](int, int) {
        ++calls;
        return RGB(1.0);
    });
    EXPECT_EQ(calls, 9);  // one forced split: a 3 x 3 set of points
    calls = 0;
    render::subdivideAreaGrid(5, 5, scene::AreaLight::kSampleEveryPoint, [&](int, int) {
        ++calls;
        return RGB(0.5);
    });
    EXPECT_EQ(calls, 25);  // every point, each traced once
}

TEST(Lights, CircularGridFillsTheDisc) {
    scene::AreaLight a;
    a.size1 = a.size2 = 5;
    a.circular = true;
    const Vec3 x{2, 0, 0}, y{0, 2, 0};
    // A corner of the square lands on the circle of radius 1 (half the axis).
    const Vec3 corner = a.gridOffset(4, 4, x, y);
    EXPECT_NEAR(length(corner), 1.0, 3e-3);
    EXPECT_NEAR(corner.x, corner.y, 1e-9);
    // An edge midpoint stays where it was.
    EXPECT_NEAR(a.gridOffset(4, 2, x, y).x, 1.0, 2e-3);
}
