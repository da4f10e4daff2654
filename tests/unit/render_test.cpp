#include <gtest/gtest.h>

#include <cmath>

#include "image/gamma.h"
#include "render/renderer.h"
#include "render/world.h"

using namespace frameray;

TEST(Gamma, Povray37Rules) {
    scene::Scene s;
    s.globals.assumedGamma = 1.0;
    s.globals.assumedGammaSet = true;
    const auto srgb = image::GammaEncoding::forScene(s.globals.assumedGammaSet,
                                                     s.globals.assumedGamma, s.languageVersion, 0);
    // Values read off povray 3.7's output: linear 0.2 -> 124/255, 0.01 -> 25/255.
    EXPECT_EQ(static_cast<int>(srgb.encode(0.2) * 255 + 0.5), 124);
    EXPECT_EQ(static_cast<int>(srgb.encode(0.01) * 255 + 0.5), 25);
    scene::Scene old;
    old.languageVersion = 3.6;
    EXPECT_DOUBLE_EQ(
        image::GammaEncoding::forScene(old.globals.assumedGammaSet, old.globals.assumedGamma,
                                       old.languageVersion, 0)
            .encode(0.5),
        0.5);
    // A scene that declares no version renders as a pre-3.7 one: no gamma
    // handling without assumed_gamma (povray 3.7 measured).
    scene::Scene undeclared;
    EXPECT_LT(undeclared.renderVersion(), 3.7);
    EXPECT_DOUBLE_EQ(
        image::GammaEncoding::forScene(false, 1.0, undeclared.renderVersion(), 0).encode(0.5), 0.5);
    undeclared.versionDeclared = true;
    EXPECT_DOUBLE_EQ(undeclared.renderVersion(), 3.7);
}

TEST(World, ClosestHitAndShadowsAcrossBvhAndPlanes) {
    scene::Scene s;
    auto sphere = std::make_shared<scene::Object>();
    sphere->shape = std::make_shared<scene::Sphere>(Vec3{0, 0, 5}, 1);
    auto far = std::make_shared<scene::Object>();
    far->shape = std::make_shared<scene::Sphere>(Vec3{0, 0, 10}, 1);
    auto plane = std::make_shared<scene::Object>();
    plane->shape = std::make_shared<scene::Plane>(Vec3{0, 0, -1}, -20);
    s.objects = {far, plane, sphere};
    render::World w(s);
    render::Hit hit;
    ASSERT_TRUE(w.intersect({{0, 0, 0}, {0, 0, 1}}, 0, scene::kInfinity, hit));
    EXPECT_EQ(hit.object, sphere.get());
    EXPECT_DOUBLE_EQ(hit.t, 4);
    ASSERT_TRUE(w.intersect({{0, 5, 0}, {0, 0, 1}}, 0, scene::kInfinity, hit));
    EXPECT_EQ(hit.object, plane.get());
    EXPECT_TRUE(w.occluded({{0, 0, 0}, {0, 0, 1}}, 0, 4.5));
    EXPECT_FALSE(w.occluded({{0, 0, 0}, {0, 0, 1}}, 0, 3.5));
}

TEST(World, TransformedObjectAtLargeScale) {
    scene::Scene s;
    auto obj = std::make_shared<scene::Object>();
    obj->shape = std::make_shared<scene::Sphere>(Vec3{0, 0, 0}, 1);
    obj->transform = Transform::scale(Vec3(1e5)).then(Transform::translate({0, 0, 1e6}));
    s.objects = {obj};
    render::World w(s);
    render::Hit hit;
    ASSERT_TRUE(w.intersect({{0, 0, 0}, {0, 0, 1}}, 0, scene::kInfinity, hit));
    EXPECT_NEAR(hit.t, 9e5, 1e-6);
}

// A scene can make NaN and huge rays (a light at <pow(-8,1/3),1,1>, a
// camera at 1e20); Embree aborts on them, so they must not reach it.
TEST(World, NanAndHugeRaysMeetNoBoundedObject) {
    scene::Scene s;
    auto sphere = std::make_shared<scene::Object>();
    sphere->shape = std::make_shared<scene::Sphere>(Vec3{0, 0, 5}, 1);
    s.objects = {sphere};
    render::World w(s);
    render::Hit hit;
    const double nan = std::nan("");
    EXPECT_FALSE(w.intersect({{nan, 0, 0}, {0, 0, 1}}, 0, scene::kInfinity, hit));
    EXPECT_FALSE(w.intersect({{0, 0, 0}, {nan, 0, 1}}, 0, scene::kInfinity, hit));
    EXPECT_FALSE(w.intersect({{0, 1e20, 0}, {0, 0, 1}}, 0, scene::kInfinity, hit));
    EXPECT_FALSE(w.occluded({{0, 0, 0}, {0, 0, 1}}, 0, nan));
    EXPECT_FALSE(w.occluded({{0, 0, -1e20}, {0, 0, 1}}, 0, scene::kInfinity));
    EXPECT_FALSE(w.occluded({{0, 0, 0}, {0, 0, 1e30}}, 0, 1));
}

// povray sees nothing 1e7 or more from a ray's origin (measured with a
// plane 0.99e7 and 1e7 in front of the camera), whatever the length of
// the ray's direction vector.
TEST(World, NothingIsSeenFromTenMillionUnitsOn) {
    scene::Scene s;
    auto plane = std::make_shared<scene::Object>();
    plane->shape = std::make_shared<scene::Plane>(Vec3{0, 0, -1}, 0);
    s.objects = {plane};
    render::World w(s);
    render::Hit hit;
    EXPECT_TRUE(w.intersect({{0, 0, -0.99e7}, {0, 0, 1}}, 0, scene::kInfinity, hit));
    EXPECT_TRUE(w.intersect({{0, 0, -0.99e7}, {0, 0, 4}}, 0, scene::kInfinity, hit));
    EXPECT_FALSE(w.intersect({{0, 0, -1.01e7}, {0, 0, 1}}, 0, scene::kInfinity, hit));
    EXPECT_FALSE(w.intersect({{0, 0, -1.01e7}, {0, 0, 0.25}}, 0, scene::kInfinity, hit));
}

TEST(Renderer, DeterministicAcrossRuns) {
    scene::Scene s;
    auto obj = std::make_shared<scene::Object>();
    obj->shape = std::make_shared<scene::Sphere>(Vec3{0, 0, 3}, 1);
    auto tex = std::make_shared<scene::Texture>();
    tex->pigment = std::make_shared<scene::Pigment>(Color(RGB(1, 0.5, 0.25)));
    obj->texture = tex;
    s.objects = {obj};
    scene::Light light;
    light.position = {5, 5, -5};
    s.lights.push_back(light);
    render::World w(s);
    render::FrameStats a, b;
    render::FrameSettings size;
    size.width = 40;
    size.height = 30;
    const auto i1 = render::renderFrame(w, size, a);
    const auto i2 = render::renderFrame(w, size, b);
    EXPECT_EQ(i1.rgb, i2.rgb);
    EXPECT_EQ(a.rays.camera, 1200u);
    // The centre pixel sees the lit sphere, a corner sees the background.
    EXPECT_GT(i1.rgb[(15 * 40 + 20) * 3], 0.1f);
    EXPECT_EQ(i1.rgb[0], 0.0f);
}

namespace {

// A sphere in front of a plane, with the given sphere finish and colour;
// rendered at 40x30, returning the ray counts.
render::RayCounts raysFor(const scene::Finish& finish, const Color& color, int quality = 9) {
    scene::Scene s;
    auto sphere = std::make_shared<scene::Object>();
    sphere->shape = std::make_shared<scene::Sphere>(Vec3{0, 0, 3}, 1);
    auto tex = std::make_shared<scene::Texture>();
    tex->pigment = std::make_shared<scene::Pigment>(color);
    tex->finish = std::make_shared<const scene::Finish>(finish);
    sphere->texture = tex;
    auto interior = std::make_shared<scene::Interior>();
    interior->ior = 1.5;
    sphere->interior = interior;
    s.objects = {sphere};
    scene::Light light;
    light.position = {5, 5, -5};
    s.lights.push_back(light);
    render::World w(s);
    render::FrameStats stats;
    render::FrameSettings settings;
    settings.width = 40;
    settings.height = 30;
    settings.quality = quality;
    render::renderFrame(w, settings, stats);
    return stats.rays;
}

}  // namespace

TEST(Renderer, TracesOnlyTheRayKindsTheSceneCallsFor) {
    // Opaque, not reflective: camera and shadow rays only.
    const render::RayCounts plain = raysFor(scene::Finish{}, Color(RGB(1)));
    EXPECT_EQ(plain.camera, 1200u);
    EXPECT_GT(plain.shadow, 0u);
    EXPECT_EQ(plain.reflection + plain.refraction + plain.transmission, 0u);

    scene::Finish mirror;
    mirror.reflection.min = mirror.reflection.max = RGB(0.5);
    const render::RayCounts reflective = raysFor(mirror, Color(RGB(1)));
    EXPECT_GT(reflective.reflection, 0u);
    EXPECT_EQ(reflective.refraction + reflective.transmission, 0u);

    // Glass of ior 1.5: rays bend entering and leaving.
    const render::RayCounts glass = raysFor(scene::Finish{}, Color(RGB(1), 0.0, 0.9));
    EXPECT_GT(glass.refraction, 0u);
    EXPECT_EQ(glass.reflection + glass.transmission, 0u);

    // Below +Q8 povray traces no reflected or transmitted rays; below +Q4
    // no shadows.
    const render::RayCounts low = raysFor(mirror, Color(RGB(1), 0.0, 0.9), 3);
    EXPECT_EQ(low.reflection + low.refraction + low.transmission + low.shadow, 0u);
}
