// Surface optics (render/optics.h) and the finish/interior parser, against
// values measured from povray 3.7 (16-bit renders of single surfaces).
#include "render/optics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "parse_support.h"
#include "render/dispersion.h"

using namespace frameray;
using namespace frameray::render;

TEST(Optics, FresnelHeadOnAndTotalReflection) {
    EXPECT_NEAR(fresnelReflectance(1.0, 1.5), 0.04, 1e-12);
    EXPECT_NEAR(fresnelReflectance(1.0, 1.0 / 1.5), 0.04, 1e-12);
    // povray: from inside glass at 20 degrees, 0.04166 of the light mirrors.
    EXPECT_NEAR(fresnelReflectance(std::cos(20 * std::numbers::pi / 180), 1.0 / 1.5), 0.04166,
                2e-4);
    // Beyond the critical angle (41.8 degrees) everything mirrors.
    EXPECT_EQ(fresnelReflectance(std::cos(50 * std::numbers::pi / 180), 1.0 / 1.5), 1.0);
    EXPECT_EQ(fresnelReflectance(1.0, 1.0), 0.0);
}

TEST(Optics, MetallicTintFollowsPovraysCurve) {
    EXPECT_NEAR(metallicFresnel(1.0), 0.0, 1e-9);
    // Measured from the tint of a metallic reflection at 60 and 30 degrees.
    EXPECT_NEAR(metallicFresnel(0.5), 0.0593, 2e-4);
    EXPECT_NEAR(metallicFresnel(std::cos(30 * std::numbers::pi / 180)), 0.0119, 5e-4);
    const RGB tint = metallicTint(1.0, 1.0, RGB(0.8, 0.5, 0.3));
    EXPECT_NEAR(tint.r, 0.8, 1e-9);
    EXPECT_NEAR(tint.b, 0.3, 1e-9);
    EXPECT_NEAR(metallicTint(0.0, 1.0, RGB(0.8, 0.5, 0.3)).g, 1.0, 1e-12);
}

TEST(Optics, ReflectanceFalloffAndFresnel) {
    scene::Reflection r;
    r.min = RGB(0.2);
    r.max = RGB(0.8);
    r.falloff = 2;
    // povray at 60 degrees: 0.2 + 0.6 * (1 - 0.5)^2 = 0.35.
    EXPECT_NEAR(reflectance(r, 0.5, 1.5, RGB(1.0)).g, 0.35, 1e-12);
    r.fresnel = true;
    EXPECT_NEAR(reflectance(r, 1.0, 1.5, RGB(1.0)).g, 0.2 + 0.6 * 0.04, 1e-12);
}

TEST(Optics, RefractionObeysSnellAndReportsTotalReflection) {
    const double a = 30 * std::numbers::pi / 180;
    const Vec3 d{std::sin(a), -std::cos(a), 0};
    const Vec3 n{0, 1, 0};
    const auto t = refractedDirection(d, n, 1.0 / 1.5);
    ASSERT_TRUE(t.has_value());
    EXPECT_NEAR(t->x, std::sin(a) / 1.5, 1e-12);
    EXPECT_LT(t->y, 0);
    const double b = 60 * std::numbers::pi / 180;
    EXPECT_FALSE(refractedDirection({std::sin(b), -std::cos(b), 0}, n, 1.5).has_value());
}

TEST(Optics, InteriorFadeLaws) {
    scene::Interior in;
    in.fadeDistance = 0.5;
    in.fadePower = 2;
    in.fadeColor = RGB(1, 0.5, 0);
    // povray through 1 unit: green 0.5 + 0.5 * 1 / (1 + 2^2) = 0.6.
    EXPECT_NEAR(interiorFade(in, 1.0).g, 0.6, 1e-12);
    EXPECT_NEAR(interiorFade(in, 1.0).b, 0.2, 1e-12);
    in.fadePower = 1001;  // exponential, per channel
    EXPECT_NEAR(interiorFade(in, 1.0).g, std::exp(-1.0), 1e-12);
    EXPECT_NEAR(interiorFade(in, 1.0).r, 1.0, 1e-12);
    in.fadePower = 0;  // the default power still halves the light
    EXPECT_NEAR(interiorFade(in, 1.0).b, 0.5, 1e-12);
    in.fadeDistance = 0;
    EXPECT_EQ(interiorFade(in, 10.0).b, 1.0);
}

TEST(Optics, ReflectionExponent) {
    const RGB c = reflectionExponent(RGB(0.25, 0.16, 0.0), 2.0);
    EXPECT_NEAR(c.r, 0.5, 1e-12);
    EXPECT_NEAR(c.g, 0.4, 1e-12);
    EXPECT_EQ(c.b, 0.0);
}

namespace {

using Parsed = test_support::ParsedScene;
std::string parseError(const std::string& text) {
    return test_support::parseErrorOf(text);
}

}  // namespace

TEST(FinishParser, ReflectionBlockAndInterior) {
    Parsed p(R"(
        #declare I = interior { ior 1.33 fade_distance 2 fade_power 1001 fade_color <0.2, 0.5, 1> }
        sphere { 0, 1 finish { reflection { 0.8 fresnel metallic } conserve_energy } interior { I } }
        sphere { 0, 1 finish { reflection { 0.1, 0.6 falloff 3 exponent 2 } metallic 0.5 } }
        sphere { 0, 1 finish { ior 1.5 reflection rgb <1, 0, 0> reflection_exponent 0.5 } }
    )");
    ASSERT_EQ(p.scene.objects.size(), 3u);
    const auto& a = *p.scene.objects[0];
    EXPECT_TRUE(a.texture->finish->reflection.fresnel);
    EXPECT_EQ(a.texture->finish->reflection.min.g, 0.0);  // one value with fresnel: the maximum
    EXPECT_EQ(a.texture->finish->reflection.max.g, 0.8);
    EXPECT_EQ(a.texture->finish->reflection.metallic, 1.0);
    EXPECT_TRUE(a.texture->finish->conserveEnergy);
    ASSERT_TRUE(a.interior);
    EXPECT_EQ(a.interior->ior, 1.33);
    EXPECT_EQ(a.interior->fadePower, 1001);
    const auto& b = *p.scene.objects[1];
    EXPECT_EQ(b.texture->finish->reflection.min.r, 0.1);
    EXPECT_EQ(b.texture->finish->reflection.falloff, 3);
    EXPECT_EQ(b.texture->finish->reflection.exponent, 2);
    EXPECT_EQ(b.texture->finish->metallic, 0.5);
    const auto& c = *p.scene.objects[2];
    ASSERT_TRUE(c.interior);  // the 2.0 finish ior fills the interior
    EXPECT_EQ(c.interior->ior, 1.5);
    EXPECT_EQ(c.texture->finish->reflection.max.r, 1.0);
    EXPECT_EQ(c.texture->finish->reflection.max.g, 0.0);
    EXPECT_EQ(c.texture->finish->reflection.exponent, 0.5);
}

TEST(Optics, IridescenceTint) {
    // povray 3.7, head-on light and view, irid_wavelength 0.5: diffuse 0.25
    // under irid { 1 thickness 0.025 } gives 0.45225.
    const RGB head = iridTint(1.0, 0.025, RGB(0.5), 1.0, 1.0);
    EXPECT_NEAR(0.25 * head.r, 0.45225, 2e-5);
    // Light at 60 degrees, view head-on: 0.23638 (with the cosine of diffuse).
    EXPECT_NEAR(0.25 * 0.5 * iridTint(1.0, 0.025, RGB(0.5), 1.0, 0.5).g, 0.23638, 2e-5);
    // amount scales the swing around 1.
    EXPECT_NEAR(iridTint(0.5, 0.1, RGB(0.7), 1.0, 1.0).b, 0.88875, 2e-5);
    scene::Iridescence irid{1.0, 0.05, 0.0};
    EXPECT_EQ(iridFilmThickness(irid, Vec3(0.3, 0.2, 0.1)), 0.05);
}

TEST(Optics, DispersionBands) {
    // povray 3.7, ior 1.5, dispersion 1.1, 7 samples: the violet band bends
    // with 1.5 * 1.1^(3/7) and carries <0.0365, 0, 0.2047>; the middle one
    // bends with the plain ior.
    scene::Interior in;
    in.ior = 1.5;
    in.dispersion = 1.1;
    EXPECT_NEAR(dispersedIor(in, dispersionBand(0, 7)), 1.5 * std::pow(1.1, 3.0 / 7.0), 1e-12);
    EXPECT_NEAR(dispersedIor(in, dispersionBand(3, 7)), 1.5, 1e-12);
    EXPECT_EQ(dispersedIor(in, SpectralBand{}), 1.5);
    const RGB violet = dispersionBandColour(0, 7);
    EXPECT_NEAR(violet.r, 0.0365, 5e-4);
    EXPECT_NEAR(violet.b, 0.2047, 5e-4);
    RGB total(0.0);
    for (int k = 0; k < 7; ++k) total += dispersionBandColour(k, 7);
    EXPECT_NEAR(total.r, 0.9938, 1e-4);
    EXPECT_NEAR(total.g, 1.0, 1e-4);
}

TEST(FinishParser, AlbedoAndBackDiffuse) {
    // Values measured with povray 3.7 on a flat-lit plane (16-bit output).
    Parsed p(R"(
        #declare F = finish { diffuse albedo 0.2 specular albedo 0.01 phong albedo 0.01 }
        sphere { 0, 1 finish { brilliance 2 diffuse albedo 0.5, 0.3 } }
        sphere { 0, 1 finish { specular albedo 0.01 roughness 0.1 phong albedo 0.01 phong_size 40 } }
        sphere { 0, 1 finish { F brilliance 2 roughness 0.1 phong_size 10 } }
        sphere { 0, 1 finish { diffuse 0.7 } }
    )");
    ASSERT_EQ(p.scene.objects.size(), 4u);
    const scene::Finish& a = *p.scene.objects[0]->texture->finish;
    EXPECT_NEAR(a.diffuse, 0.75, 1e-12);
    EXPECT_NEAR(a.diffuseBack, 0.45, 1e-12);
    const scene::Finish& b = *p.scene.objects[1]->texture->finish;
    EXPECT_NEAR(b.specular, 0.01524, 1e-5);
    EXPECT_NEAR(b.phong, 0.205, 1e-12);
    // Converted when F closed; the later block does not convert again.
    const scene::Finish& c = *p.scene.objects[2]->texture->finish;
    EXPECT_NEAR(c.diffuse, 0.2, 1e-12);
    EXPECT_NEAR(c.specular, 0.0275, 1e-4);
    EXPECT_NEAR(c.phong, 0.205, 1e-12);
    EXPECT_EQ(p.scene.objects[3]->texture->finish->diffuseBack, 0.0);
}

TEST(FinishParser, EffectsParse) {
    Parsed p(R"(
        sphere { 0, 1 finish { crand 0.1 irid { 0.3 thickness 0.2 turbulence 0.4 } }
                 interior { ior 1.5 dispersion 1.1 dispersion_samples 9 caustics 0.5 } }
        sphere { 0, 1 interior { dispersion_samples 1 } }
    )");
    const auto& a = *p.scene.objects[0];
    EXPECT_EQ(a.texture->finish->crand, 0.1);
    EXPECT_EQ(a.texture->finish->irid.amount, 0.3);
    EXPECT_EQ(a.texture->finish->irid.thickness, 0.2);
    EXPECT_EQ(a.texture->finish->irid.turbulence, 0.4);
    ASSERT_TRUE(a.interior);
    EXPECT_EQ(a.interior->dispersion, 1.1);
    EXPECT_EQ(a.interior->dispersionSamples, 9);
    EXPECT_EQ(a.interior->caustics, 0.5);
    EXPECT_EQ(p.scene.objects[1]->interior->dispersionSamples, 2);  // at least two bands
    // irid needs its amount.
    EXPECT_NE(parseError("sphere { 0, 1 finish { irid { thickness 0.2 } } }"), "");
}
