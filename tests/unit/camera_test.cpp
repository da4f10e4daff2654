// Camera ray generation per projection (values measured from povray 3.7
// with a direction-probe scene), camera parsing, and focal blur helpers.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "render/camera_rays.h"
#include "render/focal_blur.h"
#include "scene/mesh_camera.h"
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
    c.blur.focalPointGiven = true;
    const CameraRays rays(c, 32, 24);
    const render::FocalBlurSampler sampler(rays);
    ASSERT_EQ(sampler.grid().size(), 19u);
    for (const auto& [x, y] : sampler.grid()) EXPECT_LE(std::hypot(x, y), 0.5);
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

// povray's aperture grids: hexagonal lattices in a fixed order, traced in
// batches (rings), jittered by half a lattice step when the count is the
// grid's size and by 0.5 / sqrt(count) otherwise.
TEST(FocalBlur, PovrayApertureGrids) {
    Camera c = makeCamera(Projection::Perspective);
    c.blur.aperture = 1;
    {
        c.blur.blurSamples = 7;
        const CameraRays rays(c, 32, 24);
        const render::FocalBlurSampler s7(rays);
        ASSERT_EQ(s7.grid().size(), 7u);
        EXPECT_NEAR(s7.grid()[0].first, -0.288675, 1e-6);
        EXPECT_EQ(s7.grid()[1], std::make_pair(0.0, 0.0));
        EXPECT_NEAR(s7.grid()[3].first, -0.144338, 1e-6);
        EXPECT_NEAR(s7.grid()[3].second, 0.25, 1e-12);
        EXPECT_NEAR(s7.gridJitter(), 0.144338, 1e-6);
        EXPECT_EQ(s7.batches(), std::vector<int>({7}));
    }
    {
        c.blur.blurSamples = 37;
        const CameraRays rays(c, 32, 24);
        const render::FocalBlurSampler s(rays);
        ASSERT_EQ(s.grid().size(), 37u);
        EXPECT_NEAR(s.grid()[5].first, -0.433013, 1e-6);
        EXPECT_NEAR(s.grid()[19].first, -0.360844, 1e-6);
        EXPECT_NEAR(s.grid()[19].second, 0.125, 1e-12);
        EXPECT_NEAR(s.gridJitter(), 0.0721688, 1e-6);
        EXPECT_EQ(s.batches(), std::vector<int>({7, 6, 6, 4, 4, 4, 4, 2}));
    }
    {
        // 120: the 37-point grid, then Halton points on the disc, one per
        // cell of a 15 x 15 coverage grid while cells are free.
        c.blur.blurSamples = 120;
        const CameraRays rays(c, 32, 24);
        const render::FocalBlurSampler s(rays);
        ASSERT_EQ(s.grid().size(), 120u);
        EXPECT_NEAR(s.gridJitter(), 0.5 / std::sqrt(120.0), 1e-12);
        std::set<std::pair<int, int>> cells;
        for (size_t i = 0; i < 120; ++i) {
            const auto [x, y] = s.grid()[i];
            EXPECT_LE(x * x + y * y, 0.25 + 1e-12);
            if (i >= 37) {
                EXPECT_TRUE(cells.emplace(int((x + 0.5) * 15), int((y + 0.5) * 15)).second);
            }
        }
        // The first Halton point (index 1 in bases 2 and 3).
        EXPECT_NEAR(s.grid()[37].first, std::sqrt(0.125) * std::cos(2 * kPi / 3), 1e-12);
    }
}

// Each ray of a blurred sample lands in one of 16 x 16 cells of the pixel,
// shifted by at most one cell: a function of the position and ray number.
TEST(FocalBlur, RayPositionsStayNearThePixel) {
    for (int n = 0; n < 40; ++n) {
        const auto [x, y] = render::FocalBlurSampler::rayPosition(10, 7, n);
        EXPECT_GE(x, 10 - 0.5 - 1.0 / 16);
        EXPECT_LT(x, 10 + 0.5);
        EXPECT_GE(y, 7 - 0.5 - 1.0 / 16);
        EXPECT_LT(y, 7 + 0.5);
        EXPECT_EQ(render::FocalBlurSampler::rayPosition(10, 7, n), std::make_pair(x, y));
    }
}

TEST(CameraRays, OmnimaxMatchesPovrayProbe) {
    // 16x12, default vectors: pixel (7, 6) and a rim pixel povray skips.
    const CameraRays rays(makeCamera(Projection::Omnimax), 16, 12);
    const Vec3 d = unitDirection(rays, 8.5, 6.5);
    EXPECT_NEAR(std::acos(d.z), 13.631 * kPi / 180, 1e-3);
    EXPECT_FALSE(rays.generate(0.5, 0.5));
}

namespace {

// The rays of pixel (x, y) of a width x height image of the scene's mesh_camera.
std::vector<scene::Ray> meshCameraRays(const scene::Scene& s, int x, int y, int width, int height) {
    std::vector<scene::Ray> rays;
    EXPECT_TRUE(s.camera.mesh);
    if (s.camera.mesh) s.camera.mesh->pixelRays(x, y, width, height, rays);
    return rays;
}

}  // namespace

TEST(MeshCamera, Distribution2NumbersFacesByTheImageColumn) {
    // Two 2 x 3 grids side by side in a 4 x 3 image. Face f of a grid is
    // the triangle at x = f, so a ray's start x tells its face; mesh 1 sits
    // at z = 5. Row y takes face row max(y - 1, 0) (as every distribution);
    // the right half's face is row * 2 + the image's column, so it starts
    // one row down its grid and its last row runs past the last face.
    const auto s = parse(
        "#declare G = mesh {\n"
        "#for (F, 0, 5) triangle { <F, 0, 0>, <F, 1, 0>, <F + 1, 0, 0> } #end }\n"
        "camera { mesh_camera { 1 2 mesh { G } mesh { G translate 5 * z } } }");
    auto startFace = [&](int x, int y, double& z) {
        const auto rays = meshCameraRays(s, x, y, 4, 3);
        EXPECT_EQ(rays.size(), 1u) << x << ", " << y;
        if (rays.empty()) return -1.0;
        z = rays[0].origin.z;
        return std::floor(rays[0].origin.x);
    };
    double z = 0;
    EXPECT_EQ(startFace(0, 0, z), 0);
    EXPECT_EQ(z, 0);
    EXPECT_EQ(startFace(1, 2, z), 3);
    EXPECT_EQ(startFace(2, 0, z), 2);  // mesh 1, face 0 * 2 + 2
    EXPECT_EQ(z, 5);
    EXPECT_EQ(startFace(3, 1, z), 3);
    EXPECT_EQ(startFace(2, 2, z), 4);
    EXPECT_TRUE(meshCameraRays(s, 3, 3, 4, 4).empty());  // face 2 * 2 + 3 = 7 > 5
    EXPECT_THROW(parse("#declare G = mesh { triangle { 0, x, y } }\n"
                       "camera { mesh_camera { 2 2 mesh { G } mesh { G } } }"),
                 sdl::SdlError);
}

TEST(MeshCamera, SmoothBlendsTheCornerNormalsAtTheUvPoint) {
    // One smooth triangle covering uv [0, 1]^2's lower-left half; pixel
    // (10, 50) of 100 x 100 is uv (0.1, 0.5): barycentric weights 0.4 (a),
    // 0.1 (b), 0.5 (c).
    const std::string mesh =
        "mesh { smooth_triangle { <0, 0, 0>, <0, 0, 1>, <2, 0, 0>, <1, 0, 1>, <0, 2, 0>, "
        "<0, 1, 1> uv_vectors <0, 0>, <1, 0>, <0, 1> } }";
    const auto flat = parse("camera { mesh_camera { 1 3 " + mesh + " } location <0, 0, 0.5> }");
    const auto smooth =
        parse("camera { mesh_camera { 1 3 " + mesh + " smooth } location <0, 0, 0.5> }");
    const Vec3 a = normalize(Vec3(0, 0, 1)), b = normalize(Vec3(1, 0, 1)),
               c = normalize(Vec3(0, 1, 1));
    const Vec3 blend = a * 0.4 + b * 0.1 + c * 0.5;
    const Vec3 point(0.2, 1.0, 0);
    const auto f = meshCameraRays(flat, 10, 50, 100, 100);
    const auto r = meshCameraRays(smooth, 10, 50, 100, 100);
    ASSERT_EQ(f.size(), 1u);
    ASSERT_EQ(r.size(), 1u);
    // The face normal is -z (cross(c - a, b - a)), the blend is not.
    expectNear(normalize(f[0].direction), {0, 0, -1}, 1e-12);
    expectNear(normalize(r[0].direction), normalize(blend), 1e-12);
    // location z moves the start along the blend as it is (shorter than 1).
    expectNear(r[0].origin, point + blend * 0.5, 1e-12);
}

TEST(MeshCamera, SmoothOverAFlatFaceIsRefused) {
    EXPECT_THROW(parse("camera { mesh_camera { 1 3 mesh { triangle { 0, x, y uv_vectors <0, 0>, "
                       "<1, 0>, <0, 1> } } smooth } }"),
                 sdl::SdlError);
    // Corner normals that agree: povray makes the triangle flat.
    EXPECT_THROW(parse("camera { mesh_camera { 1 3 mesh { smooth_triangle { 0, z, x, z, y, z "
                       "uv_vectors <0, 0>, <1, 0>, <0, 1> } } smooth } }"),
                 sdl::SdlError);
    EXPECT_NO_THROW(
        parse("camera { mesh_camera { 1 3 mesh { triangle { 0, x, y uv_vectors <0, 0>, "
              "<1, 0>, <0, 1> } } } }"));
}
