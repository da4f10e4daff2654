// Atmosphere: parsing of background, fog, sky_sphere and rainbow as POV-Ray
// 3.7 does, and render::AtmosphereView's formulas on hand-computed cases.
#include "render/atmosphere.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "parse_support.h"
#include "sdl/interpreter.h"

using namespace frameray;

namespace {

using Parsed = test_support::ParsedScene;
std::string parseError(const std::string& text) {
    return test_support::parseErrorOf(text);
}

constexpr double kPi = std::numbers::pi;

void expectRGB(const RGB& c, double r, double g, double b, double tol = 1e-12) {
    EXPECT_NEAR(c.r, r, tol);
    EXPECT_NEAR(c.g, g, tol);
    EXPECT_NEAR(c.b, b, tol);
}

}  // namespace

// --- parsing ---------------------------------------------------------------

TEST(AtmosphereParse, FogItemsAndDefaults) {
    Parsed p(
        "fog { distance 12 color rgbft <0.2, 0.4, 0.6, 0.5, 0.25> }\n"
        "fog { fog_type 2 distance 3 rgb 1 fog_offset 1.5 fog_alt 0.5 up <0, 2, 0> rotate z * 90 "
        "}");
    const auto& fogs = p.scene.atmosphere.fogs;
    ASSERT_EQ(fogs.size(), 2u);
    EXPECT_EQ(fogs[0].kind, scene::Fog::Kind::Constant);
    EXPECT_DOUBLE_EQ(fogs[0].distance, 12);
    EXPECT_NEAR(fogs[0].color.filter, 0.5, 1e-7);
    EXPECT_NEAR(fogs[0].color.transmit, 0.25, 1e-7);
    EXPECT_DOUBLE_EQ(fogs[0].turbulenceDepth, 0.5);
    EXPECT_EQ(fogs[1].kind, scene::Fog::Kind::Ground);
    EXPECT_DOUBLE_EQ(fogs[1].offset, 1.5);
    EXPECT_DOUBLE_EQ(fogs[1].altitude, 0.5);
    // up is turned by the rotation and normalised at the end.
    EXPECT_NEAR(fogs[1].up.x, -1, 1e-12);
    EXPECT_NEAR(fogs[1].up.y, 0, 1e-12);
    EXPECT_EQ(p.sink.warnings.find("fog"), std::string::npos) << p.sink.warnings;
}

TEST(AtmosphereParse, FogWarningsAsPovray) {
    Parsed p("#declare D = 7;\nfog { D rgb 1 fog_type 3 translate 1 }");
    const auto& fog = p.scene.atmosphere.fogs.at(0);
    EXPECT_DOUBLE_EQ(fog.distance, 7);
    EXPECT_EQ(fog.kind, scene::Fog::Kind::Constant);  // unknown types are constant fog
    EXPECT_NE(p.sink.warnings.find("Should use distance keyword."), std::string::npos);
    EXPECT_NE(p.sink.warnings.find("Unknown fog type."), std::string::npos);
    EXPECT_NE(p.sink.warnings.find("A fog's up vector can't be translated."), std::string::npos);
}

TEST(AtmosphereParse, FogTurbulence) {
    Parsed p(
        "fog { distance 3 rgb 1 turbulence <0.5, 1, 2> octaves 3 omega 0.4 lambda 3 "
        "turb_depth 0.3 }\n"
        "fog { distance 3 rgb 1 octaves 4 }\n"
        "fog { distance 3 rgb 1 turb_depth 0.3 }");
    ASSERT_EQ(p.scene.atmosphere.fogs.size(), 3u);
    const auto& f = p.scene.atmosphere.fogs[0];
    ASSERT_TRUE(f.turbulence);
    EXPECT_EQ(f.turbulence->amount.z, 2.0);
    EXPECT_EQ(f.turbulence->octaves, 3);
    EXPECT_FLOAT_EQ(f.turbulence->omega, 0.4f);
    EXPECT_FLOAT_EQ(f.turbulence->lambda, 3.0f);
    EXPECT_EQ(f.turbulenceDepth, 0.3);
    // Any turbulence item makes one (amount 0: measured, it still changes
    // the fog); turb_depth alone does not.
    ASSERT_TRUE(p.scene.atmosphere.fogs[1].turbulence);
    EXPECT_EQ(p.scene.atmosphere.fogs[1].turbulence->amount.x, 0.0);
    EXPECT_FALSE(p.scene.atmosphere.fogs[2].turbulence);
}

TEST(AtmosphereParse, SkySphere) {
    Parsed p(
        "sky_sphere { pigment { rgb 1 } }\n"
        "sky_sphere { pigment { rgb <1, 0, 0> } pigment { rgbt <0, 1, 0, 0.5> } emission 0.5 "
        "translate y }");
    ASSERT_TRUE(p.scene.atmosphere.skySphere);
    const auto& sky = *p.scene.atmosphere.skySphere;
    EXPECT_EQ(sky.pigments.size(), 2u);  // the last sky_sphere replaces the first
    expectRGB(sky.emission, 0.5, 0.5, 0.5, 1e-7);
    EXPECT_NEAR(sky.transform.inversePoint({0, 1, 0}).y, 0, 1e-12);
    EXPECT_NE(p.sink.warnings.find("Only one sky-sphere allowed (last one will be used)."),
              std::string::npos);
    EXPECT_NE(parseError("sky_sphere { emission 1 }").find("Empty sky_sphere statement."),
              std::string::npos);
}

TEST(AtmosphereParse, DeclaredFogAndSkySphere) {
    Parsed p(
        "#declare F = fog { distance 5 rgb <1, 0, 0> }\n"
        "#declare S = sky_sphere { pigment { rgb 1 } emission 0.5 }\n"
        "fog { F fog_type 2 }\nsky_sphere { S pigment { rgbt <0, 0, 1, 0.5> } }");
    const auto& fog = p.scene.atmosphere.fogs.at(0);
    EXPECT_DOUBLE_EQ(fog.distance, 5);
    EXPECT_EQ(fog.kind, scene::Fog::Kind::Ground);
    EXPECT_NEAR(fog.color.rgb.r, 1, 1e-7);
    ASSERT_TRUE(p.scene.atmosphere.skySphere);
    EXPECT_EQ(p.scene.atmosphere.skySphere->pigments.size(), 2u);
    EXPECT_NEAR(p.scene.atmosphere.skySphere->emission.g, 0.5, 1e-7);
    EXPECT_NE(parseError("#declare R = rainbow { direction z }").find("not supported yet"),
              std::string::npos);
}

TEST(AtmosphereParse, RainbowAnglesAndVectors) {
    Parsed p(
        "rainbow { angle 42 width 4 direction <0, 0, 2> up <0, 1, 1> arc_angle 120 "
        "color_map { [0 rgb 0] [1 rgb 1] } }");
    const auto& r = p.scene.atmosphere.rainbows.at(0);
    EXPECT_NEAR(r.bandStart, 40 * kPi / 180, 1e-12);
    EXPECT_NEAR(r.width, 4 * kPi / 180, 1e-12);
    // arc_angle is kept as half the angle, in radians; with no
    // falloff_angle the falloff starts at the arc's end.
    EXPECT_NEAR(r.arcAngle, 60 * kPi / 180, 1e-12);
    EXPECT_DOUBLE_EQ(r.falloffAngle, r.arcAngle);
    EXPECT_DOUBLE_EQ(r.falloffWidth, 0);
    EXPECT_DOUBLE_EQ(r.distance, 1e7);
    EXPECT_NEAR(r.antisolar.z, 1, 1e-12);
    // up made perpendicular to the direction.
    EXPECT_NEAR(r.up.y, 1, 1e-12);
    EXPECT_NEAR(r.up.z, 0, 1e-12);
    EXPECT_NEAR(r.right.x, 1, 1e-12);
    ASSERT_TRUE(r.colorMap);

    // Only falloff_angle: the arc keeps povray's raw default 180.
    Parsed q("rainbow { angle 42 width 4 direction z falloff_angle 90 }");
    const auto& s = q.scene.atmosphere.rainbows.at(0);
    EXPECT_DOUBLE_EQ(s.arcAngle, 180.0);
    EXPECT_NEAR(s.falloffWidth, 180.0 - kPi / 4, 1e-12);
    EXPECT_FALSE(s.colorMap);
}

TEST(AtmosphereParse, RainbowErrors) {
    EXPECT_NE(
        parseError("rainbow { angle 42 width 4 }").find("Rainbow's direction vector is zero."),
        std::string::npos);
    EXPECT_NE(parseError("rainbow { direction y }")
                  .find("Rainbow's up and direction vector are co-linear."),
              std::string::npos);
    EXPECT_NE(
        parseError("rainbow { direction z arc_angle 400 }").find("Illegal arc angle in rainbow"),
        std::string::npos);
    EXPECT_NE(parseError("rainbow { direction z arc_angle 40 falloff_angle 60 }")
                  .find("Arc angle is smaller than falloff angle in rainbow."),
              std::string::npos);
}

// --- evaluation --------------------------------------------------------------

TEST(AtmosphereView, ConstantFogOverDistance) {
    scene::Scene s;
    scene::Fog fog;
    fog.distance = 10;
    fog.color = Color(RGB(0.5, 0.6, 0.7));
    s.atmosphere.fogs.push_back(fog);
    const render::AtmosphereView view(s, true);
    // An unnormalised direction: t = 2 along <0,0,3> is 6 units away.
    const scene::Ray ray{{0, 0, 0}, {0, 0, 3}};
    const Color seen = view.along(ray, 2, Color(RGB(1, 0, 0)));
    const double k = std::exp(-0.6);
    expectRGB(seen.rgb, k + 0.5 * (1 - k), 0.6 * (1 - k), 0.7 * (1 - k));
    // A miss sees the fog colour (depth 2e10).
    expectRGB(view.miss(ray).rgb, 0.5, 0.6, 0.7);
    // Below quality 9 fog is not traced.
    const render::AtmosphereView flat(s, false);
    expectRGB(flat.along(ray, 2, Color(RGB(1, 0, 0))).rgb, 1, 0, 0);
    expectRGB(flat.miss(ray).rgb, 0, 0, 0);
}

TEST(AtmosphereView, FogFilterAndTransmit) {
    scene::Scene s;
    scene::Fog fog;
    fog.distance = 1;
    fog.color = Color(RGB(0.2, 0.4, 0.8), 0.5, 0.25);
    s.atmosphere.fogs.push_back(fog);
    const render::AtmosphereView view(s, true);
    // Far away the fog keeps its transmit (0.25) of what is behind,
    // tinted half by the fog colour (filter 0.5).
    const Color seen = view.throughFogs({0, 0, 0}, {0, 0, 1}, 100, Color(RGB(1)));
    const double keep = 0.25;
    expectRGB(seen.rgb, 0.2 * (1 - keep) + keep * (0.5 + 0.5 * 0.2),
              0.4 * (1 - keep) + keep * (0.5 + 0.5 * 0.4),
              0.8 * (1 - keep) + keep * (0.5 + 0.5 * 0.8));
}

TEST(AtmosphereView, GroundFogDensity) {
    scene::Scene s;
    scene::Fog fog;
    fog.kind = scene::Fog::Kind::Ground;
    fog.distance = 4;
    fog.offset = 1;
    fog.altitude = 2;
    fog.color = Color(RGB(1));
    s.atmosphere.fogs.push_back(fog);
    const render::AtmosphereView view(s, true);
    // Entirely below fog_offset: as dense as constant fog.
    const Color low = view.throughFogs({0, 0.5, 0}, {1, 0, 0}, 3, Color(RGB(0)));
    EXPECT_NEAR(low.rgb.r, 1 - std::exp(-3.0 / 4), 1e-12);
    // Level at height 3 (h = 1 in fog_alt units): density 1 / (1 + 1).
    const Color level = view.throughFogs({0, 3, 0}, {1, 0, 0}, 3, Color(RGB(0)));
    EXPECT_NEAR(level.rgb.r, 1 - std::exp(-3.0 * 0.5 / 4), 1e-12);
    // Rising from h = 0 to h = 2: the mean density is atan(2) / 2.
    const Color rising = view.throughFogs({0, 1, 0}, {0, 1, 0}, 4, Color(RGB(0)));
    EXPECT_NEAR(rising.rgb.r, 1 - std::exp(-4 * (std::atan(2.0) / 2) / 4), 1e-12);
    // Crossing from below (h = -1) to h = 1: (atan(1) - (-1)) / 2.
    const Color crossing = view.throughFogs({0, -1, 0}, {0, 1, 0}, 4, Color(RGB(0)));
    EXPECT_NEAR(crossing.rgb.r, 1 - std::exp(-4 * ((std::atan(1.0) + 1) / 2) / 4), 1e-12);
}

TEST(AtmosphereView, SeveralFogsCombine) {
    scene::Scene s;
    scene::Fog a, b;
    a.distance = 2;
    a.color = Color(RGB(1, 0, 0));
    b.distance = 5;
    b.color = Color(RGB(0, 0, 1));
    s.atmosphere.fogs = {a, b};
    const render::AtmosphereView view(s, true);
    const Color seen = view.throughFogs({0, 0, 0}, {0, 0, 1}, 1, Color(RGB(0, 1, 0)));
    const double ka = std::exp(-0.5), kb = std::exp(-0.2);
    expectRGB(seen.rgb, 1 - ka, ka * kb, 1 - kb);
}

TEST(AtmosphereView, SkyLayersOverBackground) {
    scene::Scene s;
    s.versionDeclared = true;  // 3.7's sky
    s.background = Color(RGB(0.2, 0.4, 0.8), 0.5, 0.25);
    const render::AtmosphereView bare(s, true);
    // The background alone: transmit lowers it, filter does not.
    expectRGB(bare.sky({0, 0, 1}).rgb, 0.15, 0.3, 0.6);

    scene::SkySphere sky;
    sky.pigments.push_back(std::make_shared<scene::Pigment>(Color(RGB(1, 0.5, 0.5), 0.5, 0.3)));
    s.atmosphere.skySphere = sky;
    s.background = Color(RGB(0.2, 0.4, 0.8));
    const render::AtmosphereView view(s, true);
    // Layer opacity 1 - 0.5 - 0.3; it passes 0.5 * colour + 0.3.
    expectRGB(view.sky({0, 0, 1}).rgb, 0.2 + 0.2 * 0.8, 0.1 + 0.4 * 0.55, 0.1 + 0.8 * 0.55);
    EXPECT_EQ(view.sky({0, 0, 1}).filter, 0);
}

TEST(AtmosphereView, LegacySkyKeepsTheBackground) {
    scene::Scene s;
    s.languageVersion = 3.6;
    s.versionDeclared = true;
    s.background = Color(RGB(0.2, 0.4, 0.8), 0, 0.5);
    const render::AtmosphereView bare(s, true);
    expectRGB(bare.sky({0, 0, 1}).rgb, 0.2, 0.4, 0.8);
    scene::SkySphere sky;
    sky.pigments.push_back(std::make_shared<scene::Pigment>(Color(RGB(1, 0.5, 0.5), 0, 0.6)));
    sky.emission = RGB(0.5);
    s.atmosphere.skySphere = sky;
    const render::AtmosphereView view(s, true);
    // 0.4 of the layer, scaled by emission, plus 0.6 of the background.
    expectRGB(view.sky({0, 0, 1}).rgb, 0.2 + 0.12, 0.1 + 0.24, 0.1 + 0.48);
}

TEST(AtmosphereView, RainbowBand) {
    scene::Scene s;
    scene::Rainbow r;
    r.bandStart = 40 * kPi / 180;
    r.width = 4 * kPi / 180;
    r.antisolar = {0, 0, 1};
    r.colorMap = scene::ColorMap({{0, Color(RGB(1, 0, 0))}, {1, Color(RGB(0, 0, 1))}});
    s.atmosphere.rainbows.push_back(r);
    s.background = Color(RGB(0, 1, 0));
    const render::AtmosphereView view(s, true);
    // 41 degrees from the antisolar point: a quarter into the band.
    const double a = 41 * kPi / 180;
    const scene::Ray inBand{{0, 0, 0}, {0, std::sin(a), std::cos(a)}};
    expectRGB(view.miss(inBand).rgb, 0.75, 0, 0.25, 1e-9);
    // Outside the band the sky is untouched.
    const scene::Ray outside{{0, 0, 0}, {0, 0, 1}};
    expectRGB(view.miss(outside).rgb, 0, 1, 0);
    // A near hit keeps most of the surface colour: exp(-depth / 1e7).
    const Color hit = view.along(inBand, 1e6, Color(RGB(0, 1, 0)));
    const double k = std::exp(-0.1);
    expectRGB(hit.rgb, 0.75 * (1 - k), k, 0.25 * (1 - k), 1e-9);
}

TEST(AtmosphereView, RainbowJitterIsAFunctionOfTheRay) {
    scene::Scene s;
    scene::Rainbow r;
    r.bandStart = 40 * kPi / 180;
    r.width = 4 * kPi / 180;
    r.jitter = 0.3;
    r.antisolar = {0, 0, 1};
    r.colorMap = scene::ColorMap({{0, Color(RGB(1, 0, 0))}, {1, Color(RGB(0, 0, 1))}});
    s.atmosphere.rainbows.push_back(r);
    const render::AtmosphereView view(s, true);
    const double a = 42 * kPi / 180;
    const scene::Ray ray{{0, 0, 0}, {0, std::sin(a), std::cos(a)}};
    const RGB first = view.miss(ray).rgb;
    const RGB again = view.miss(ray).rgb;
    EXPECT_EQ(first.r, again.r);
    EXPECT_EQ(first.b, again.b);
    // The jittered index stays within +-0.3 of the unjittered 0.5.
    EXPECT_GE(first.r, 0.2 - 1e-12);
    EXPECT_LE(first.r, 0.8 + 1e-12);
}
