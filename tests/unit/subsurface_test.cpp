// Subsurface light transport: parsing of finish { subsurface { } },
// mm_per_unit and global_settings { subsurface { } }, and the model's
// formulas (render/subsurface.h).
#include "render/subsurface.h"

#include <gtest/gtest.h>

#include <cmath>

#include "parse_support.h"

using namespace frameray;
namespace ss = frameray::render::subsurface;

TEST(Subsurface, ParsesFinishAndGlobalSettings) {
    test_support::ParsedScene p(
        "global_settings { mm_per_unit 40 subsurface { samples 400, 40 } }\n"
        "sphere { 0, 1 finish { subsurface { translucency <5, 3, 1> } } }\n");
    ASSERT_TRUE(p.scene.globals.subsurface.has_value());
    EXPECT_EQ(p.scene.globals.mmPerUnit, 40.0);
    EXPECT_EQ(p.scene.globals.subsurface->samplesDiffuse, 400);
    EXPECT_EQ(p.scene.globals.subsurface->samplesSingle, 40);
    const scene::Finish& f = *p.scene.objects.at(0)->texture->finish;
    EXPECT_TRUE(f.subsurface);
    EXPECT_EQ(f.translucency.r, 5.0);
    EXPECT_EQ(f.translucency.b, 1.0);
}

TEST(Subsurface, DefaultsAndUnsupportedRadiosity) {
    test_support::ParsedScene p("sphere { 0, 1 }\n");
    EXPECT_FALSE(p.scene.globals.subsurface.has_value());
    EXPECT_EQ(p.scene.globals.mmPerUnit, 10.0);  // povray 3.7's default
    test_support::ParsedScene q("global_settings { subsurface { } }\n");
    EXPECT_EQ(q.scene.globals.subsurface->samplesDiffuse, 50);
    EXPECT_EQ(q.scene.globals.subsurface->samplesSingle, 50);
    EXPECT_NE(test_support::parseErrorOf("global_settings { subsurface { radiosity on } }")
                  .find("not supported yet"),
              std::string::npos);
}

TEST(Subsurface, FresnelTransmittanceHeadOnAndGrazing) {
    // Head-on at ior 1.5: ((n - 1) / (n + 1))^2 = 0.04 is reflected.
    EXPECT_NEAR(ss::fresnelTransmittance(1.0, 1.5), 0.96, 1e-12);
    EXPECT_NEAR(ss::fresnelTransmittance(1e-9, 1.5), 0.0, 1e-6);
    EXPECT_NEAR(ss::fresnelTransmittance(1.0, 1.0), 1.0, 1e-12);
}

TEST(Subsurface, ReducedAlbedoInvertsTheDiffuseReflectance) {
    const double ior = 1.45;
    const double fdr = ss::diffuseFresnelReflectance(ior);
    const double A = (1 + fdr) / (1 - fdr);
    EXPECT_EQ(ss::reducedAlbedo(0.0, ior), 0.0);
    EXPECT_EQ(ss::reducedAlbedo(1.0, ior), 1.0);
    EXPECT_NEAR(ss::diffuseReflectance(A, 1.0), 1.0, 1e-12);
    // At the table's values the inverse is exact; between them linear.
    for (double rd : {0.01, 0.2, 0.5, 0.83, 0.99})
        EXPECT_NEAR(ss::diffuseReflectance(A, ss::reducedAlbedo(rd, ior)), rd, 1e-9) << rd;
    const double mid = ss::reducedAlbedo(0.505, ior);
    EXPECT_NEAR(mid, 0.5 * (ss::reducedAlbedo(0.50, ior) + ss::reducedAlbedo(0.51, ior)), 1e-12);
    // Values outside [0, 1] are clamped.
    EXPECT_EQ(ss::reducedAlbedo(1.7, ior), 1.0);
}

TEST(Subsurface, DipoleFallsWithDistanceAndIntegratesToRd) {
    const double sPrime = 2.0, a = 0.05, eta = 1.3;
    const double fdr = ss::diffuseFresnelReflectance(eta);
    const double A = (1 + fdr) / (1 - fdr);
    EXPECT_GT(ss::dipole(0.0, sPrime, a, A), ss::dipole(1.0, sPrime, a, A));
    // Its integral over the plane is the
    // total diffuse reflectance of the same albedo.
    double sum = 0;
    const double dr = 0.001;
    for (double r = dr / 2; r < 200; r += dr)
        sum += ss::dipole(r * r, sPrime, a, A) * 2 * M_PI * r * dr;
    const double alphaPrime = sPrime / (sPrime + a);
    EXPECT_NEAR(sum, ss::diffuseReflectance(A, alphaPrime), 2e-3);
}
