// Camera ray generation per projection (values measured from povray 3.7
// with a direction-probe scene), camera parsing, and focal blur helpers.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render/camera_rays.h"
#include "render/focal_blur.h"
#include "sdl/interpreter.h"
#include "util/chi_square.h"

using namespace frameray;
using frameray::render::CameraRays;
using frameray::scene::Camera;
using frameray::scene::Projection;

namespace {

constexpr double kPi = std::numbers::pi;

Camera makeCamera(Projection p, double angle = 0) {
    Camera c;
    c.projection = p;
    c.angle = angle > 0 ? angle : scene::defaultAngle(p);
    return c;
}

Vec3 unitDirection(const CameraRays& rays, double x, double y) {
    const auto ray = rays.generate(x, y);
    EXPECT_TRUE(ray.has_value());
    return ray ? normalize(ray->direction) : Vec3{};
}

void expectNear(const Vec3& a, const Vec3& b, double eps = 1e-4) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

scene::Scene parse(const std::string& text) {
    sdl::FrameContext ctx;
    sdl::TokenCache cache;
    struct : sdl::MessageSink {
        void message(sdl::Stream, const std::string&) override {}
    } sink;
    sdl::Interpreter interp(ctx, cache, sink);
    return interp.parseText("c.pov", text);
}

}  // namespace

TEST(CameraRays, CentreRayLooksAlongDirectionForEveryProjection) {
    for (Projection p : {Projection::Perspective, Projection::Fisheye, Projection::UltraWideAngle,
                         Projection::Cylinder1, Projection::Cylinder2, Projection::Cylinder3,
                         Projection::Cylinder4, Projection::Spherical, Projection::Panoramic,
                         Projection::Orthographic}) {
        const CameraRays rays(makeCamera(p), 160, 120);
        expectNear(unitDirection(rays, 80, 60), {0, 0, 1}, 1e-9);
    }
}

TEST(CameraRays, PerspectiveCornerMatchesPovray) {
    // Pixel (0,0) of an 8x6 image, probed from povray.
    const CameraRays rays(makeCamera(Projection::Perspective), 8, 6);
    expectNear(unitDirection(rays, 0.5, 0.5), {-0.47317, 0.33883, 0.81320});
}

TEST(CameraRays, OrthographicMovesTheOrigin) {
    const CameraRays rays(makeCamera(Projection::Orthographic), 100, 100);
    const auto ray = rays.generate(0, 0);
    ASSERT_TRUE(ray);
    expectNear(ray->origin, {-0.665, 0.5, 0}, 1e-12);
    expectNear(ray->direction, {0, 0, 1}, 1e-12);
}

TEST(CameraRays, FisheyeTracesOnlyInsideItsCircle) {
    const CameraRays rays(makeCamera(Projection::Fisheye, 180), 120, 120);
    // Right length 1.33 stretches the circle across: the image's right edge
    // centre lies outside it, a point at 1/1.33 of the half-width is 90
    // degrees off the axis.
    EXPECT_FALSE(rays.generate(119.9, 60));
    expectNear(unitDirection(rays, 60 + 59.999 / 1.33, 60), {1, 0, 0}, 1e-4);
}

TEST(CameraRays, SphericalMapsLongitudeAndLatitude) {
    // Default angles 360 x 180: the left edge looks backwards, the top up.
    const CameraRays rays(makeCamera(Projection::Spherical), 360, 180);
    expectNear(unitDirection(rays, 0, 90), {0, 0, -1}, 1e-9);
    expectNear(unitDirection(rays, 90, 90), {-1, 0, 0}, 1e-9);
    expectNear(unitDirection(rays, 180, 0), {0, 1, 0}, 1e-9);
    Camera narrow = makeCamera(Projection::Spherical, 180);
    narrow.verticalAngle = 60;
    const CameraRays narrowRays(narrow, 180, 60);
    const Vec3 top = unitDirection(narrowRays, 90, 0);
    EXPECT_NEAR(std::asin(top.y), kPi / 6, 1e-9);
}

TEST(CameraRays, PanoramicSpansHalfACircle) {
    const CameraRays rays(makeCamera(Projection::Panoramic), 160, 120);
    expectNear(unitDirection(rays, 0, 60), {-1, 0, 0}, 1e-9);
    expectNear(unitDirection(rays, 160, 60), {1, 0, 0}, 1e-9);
    EXPECT_FALSE(rays.generate(80, 0));  // the pole: tan(90 degrees)
}

TEST(CameraRays, CylindersMeasuredFromPovray) {
    // 16x12 probes, pixel (0,0) centre, default camera vectors, angle 90.
    const CameraRays c1(makeCamera(Projection::Cylinder1), 16, 12);
    const Vec3 d1 = unitDirection(c1, 0.5, 0.5);
    EXPECT_NEAR(std::atan2(d1.x, d1.z) * 180 / kPi, -42.1875, 1e-3);
    const CameraRays c3(makeCamera(Projection::Cylinder3), 16, 12);
    const auto r3 = c3.generate(0.5, 0.5);
    ASSERT_TRUE(r3);
    EXPECT_NEAR(r3->origin.y, 0.5 - 0.5 / 12, 1e-12);  // viewpoint moves up the axis
}

TEST(CameraParse, DeferredLookAtAndTransformsKeepHandedness) {
    // Transformations are applied after look_at wherever they appear.
    const auto a = parse("camera { location 0 rotate y*30 look_at z }").camera;
    const auto b = parse("camera { location 0 look_at z rotate y*30 }").camera;
    expectNear(a.direction, b.direction, 1e-12);
    EXPECT_NEAR(a.direction.x, std::sin(kPi / 6), 1e-12);
    // A left-handed right vector stays left-handed through look_at.
    const auto left = parse("camera { right -1.33*x location <0,0,-5> look_at 0 }").camera;
    EXPECT_LT(left.right.x, 0);
}

TEST(CameraParse, TypesAnglesAndErrors) {
    const auto s = parse("camera { spherical angle 200, 60 }").camera;
    EXPECT_EQ(s.projection, Projection::Spherical);
    EXPECT_EQ(s.angle, 200);
    EXPECT_EQ(s.verticalAngle, 60);
    EXPECT_EQ(parse("camera { cylinder 3 }").camera.projection, Projection::Cylinder3);
    EXPECT_EQ(parse("camera { fisheye }").camera.angle, 90);
    // Orthographic angle: right sized from the look_at distance.
    const auto o = parse("camera { orthographic location <0,0,-5> look_at 0 angle 90 }").camera;
    EXPECT_NEAR(length(o.right), 10, 1e-9);
    EXPECT_THROW(parse("camera { cylinder 5 }"), sdl::SdlError);
    EXPECT_THROW(parse("camera { location z look_at z }"), sdl::SdlError);
    EXPECT_THROW(parse("camera { location 0 fisheye }"), sdl::SdlError);
    EXPECT_THROW(parse("#declare C = camera { }\ncamera { C location 0 }"), sdl::SdlError);
    EXPECT_THROW(parse("camera { mesh_camera { 1 0 } }"), sdl::SdlError);
    const auto blur =
        parse("camera { aperture 0.5 blur_samples 4, 30 focal_point <0,0,3> }").camera;
    EXPECT_TRUE(blur.blur.enabled());
    EXPECT_EQ(blur.blur.minSamples, 4);
    EXPECT_EQ(blur.blur.blurSamples, 30);
}

TEST(CameraParse, IdentifierAcceptsTransformations) {
    const auto c =
        parse("#declare C = camera { fisheye location <0,0,-5> }\ncamera { C translate x }").camera;
    EXPECT_EQ(c.projection, Projection::Fisheye);
    expectNear(c.location, {1, 0, -5}, 1e-12);
}

TEST(FocalBlur, ChiSquareQuantile) {
    // P(chi2_1 > 0.01579) = 0.9, P(chi2_10 > 4.865) = 0.9 (standard tables).
    EXPECT_NEAR(chiSquareUpperTailInverse(1, 0.9), 0.01579, 1e-4);
    EXPECT_NEAR(chiSquareUpperTailInverse(10, 0.9), 4.8652, 1e-3);
}

TEST(FocalBlur, GridInsideDiscAndDeterministicSamples) {
    Camera c = makeCamera(Projection::Perspective);
    c.blur.aperture = 1;
    c.blur.blurSamples = 19;
    c.blur.focalPoint = {0, 0, 5};
    const CameraRays rays(c, 32, 24);
    const render::FocalBlurSampler sampler(rays);
    ASSERT_EQ(sampler.grid().size(), 19u);
    for (const auto& [x, y] : sampler.grid()) EXPECT_LE(std::hypot(x, y), 1.0);
    // Thresholds grow with the sample count.
    EXPECT_LT(sampler.thresholds()[0], sampler.thresholds()[18]);
    // Every blurred ray passes through the focal plane near the unblurred
    // ray's point there, and the same position gives the same result.
    int traced = 0;
    const auto trace = [&](const scene::Ray& r) {
        ++traced;
        const double t = (5 - r.origin.z) / r.direction.z;
        const Vec3 p = r.at(t);
        EXPECT_LT(std::hypot(p.x, p.y), 5 * 0.7);  // within the pixel's cone
        return RGB(p.x, p.y, 0);
    };
    const auto a = sampler.sample(16, 12, trace);
    const auto b = sampler.sample(16, 12, trace);
    EXPECT_EQ(a.rgb.r, b.rgb.r);
    EXPECT_GT(traced, 0);
}

TEST(CameraRays, OmnimaxMatchesPovrayProbe) {
    // 16x12, default vectors: pixel (7, 6) and a rim pixel povray skips.
    const CameraRays rays(makeCamera(Projection::Omnimax), 16, 12);
    const Vec3 d = unitDirection(rays, 8.5, 6.5);
    EXPECT_NEAR(std::acos(d.z), 13.631 * kPi / 180, 1e-3);
    EXPECT_FALSE(rays.generate(0.5, 0.5));
}
