// Map-based textures: texture_map and list-pattern textures, tiles,
// average, pigment_map bodies, declared maps, normal_map and slope_map.
#include <gtest/gtest.h>

#include "parse_support.h"

using namespace frameray;
using namespace frameray::scene;
using test_support::ParsedScene;
using test_support::parseErrorOf;

namespace {

const Texture& firstTexture(const ParsedScene& p) {
    return *p.scene.objects.at(0)->texture;
}

// The textures a map picks at texture point q, with their weights.
std::vector<std::pair<const Texture*, double>> picks(const TextureMap& map, const Vec3& q) {
    std::vector<std::pair<const Texture*, double>> out;
    map.visit(q, [&](const Texture& t, double w) { out.emplace_back(&t, w); });
    return out;
}

double red(const Texture& t, const Vec3& p) {
    return t.pigment->at(t.transform.inversePoint(p)).rgb.r;
}

}  // namespace

TEST(TextureMaps, TextureMapBlendsTwoEntries) {
    ParsedScene p(R"(
#declare TA = texture { pigment { rgb <1, 0, 0> } }
plane { y, 0 texture { gradient x texture_map { [0.2 TA] [0.6 pigment { rgb 0.5 } finish { phong 1 }] } } })");
    const Texture& tex = firstTexture(p);
    ASSERT_TRUE(tex.map);
    ASSERT_EQ(tex.map->entries.size(), 2u);
    EXPECT_DOUBLE_EQ(tex.map->entries[1].texture->finish->phong, 1.0);
    auto at = picks(*tex.map, Vec3(0.3, 0, 0));
    ASSERT_EQ(at.size(), 2u);
    EXPECT_NEAR(at[0].second, 0.75, 1e-9);
    EXPECT_NEAR(at[1].second, 0.25, 1e-9);
    EXPECT_DOUBLE_EQ(red(*at[0].first, Vec3()), 1.0);
    // Below the first entry only the first texture.
    at = picks(*tex.map, Vec3(0.1, 0, 0));
    ASSERT_EQ(at.size(), 1u);
    EXPECT_DOUBLE_EQ(at[0].second, 1.0);
}

TEST(TextureMaps, ListPatternTexturesAndTiles) {
    ParsedScene p(R"(
plane { y, 0 texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } }
plane { y, 0 texture { tiles { texture { pigment { rgb 1 } } tile2 texture { pigment { rgb 0 } } } } })");
    for (int i = 0; i < 2; ++i) {
        const Texture& tex = *p.scene.objects[i]->texture;
        ASSERT_TRUE(tex.map);
        EXPECT_EQ(tex.map->mode, TextureMap::Mode::List);
        const auto at = picks(*tex.map, Vec3(0.5, 0.5, 0.5));
        ASSERT_EQ(at.size(), 1u);
        // checker's first texture fills the cell at the origin; tiles puts
        // its first texture in the other cells (measured with povray).
        EXPECT_DOUBLE_EQ(red(*at[0].first, Vec3()), i == 0 ? 1.0 : 0.0);
    }
}

TEST(TextureMaps, TransformationsMoveThePatternAndTheEntries) {
    ParsedScene p(R"(
plane { y, 0 texture { gradient x texture_map { [0 pigment { gradient x }] [1 pigment { gradient x }] } scale 4 } translate x })");
    const Texture& tex = firstTexture(p);
    ASSERT_TRUE(tex.map);
    EXPECT_TRUE(tex.transform.isIdentity());
    // Pattern value at x = 3: (3 - 1) / 4.
    const auto at = picks(*tex.map, Vec3(3, 0, 0));
    ASSERT_EQ(at.size(), 2u);
    EXPECT_NEAR(at[1].second, 0.5, 1e-9);
    EXPECT_NEAR(red(*at[0].first, Vec3(3, 0, 0)), 0.5, 1e-9);
}

TEST(TextureMaps, TurbulenceDisplacesTheEntries) {
    ParsedScene p(R"(
plane { y, 0 texture { bozo warp { turbulence 0.5 } texture_map { [0 pigment { rgb 1 }] [1 pigment { rgb 0 }] } scale 2 } }
plane { y, 0 texture { bozo texture_map { [0 pigment { rgb 1 }] [1 pigment { rgb 0 }] } scale 2 } })");
    const Vec3 q(0.3, 0.7, 1.1);
    const Vec3 warped = p.scene.objects[0]->texture->map->entryPoint(q);
    EXPECT_GT(length(warped - q), 1e-3);
    const Vec3 plain = p.scene.objects[1]->texture->map->entryPoint(q);
    EXPECT_EQ(plain.x, q.x);
    EXPECT_EQ(plain.y, q.y);
}

TEST(TextureMaps, ShadowsPassBlendedFilter) {
    ParsedScene p(R"(
sphere { 0, 1 texture { gradient x texture_map { [0 pigment { rgbt <1, 1, 1, 1> }] [1 pigment { rgb 0 }] } } })");
    const RGB through = firstTexture(p).throughAt(Vec3(0.25, 0, 0));
    EXPECT_NEAR(through.r, 0.75, 1e-9);
}

TEST(TextureMaps, AverageWeighsEveryEntry) {
    ParsedScene p(R"(
plane { y, 0 texture { average texture_map { [1 pigment { rgb 1 }] [3 pigment { rgb 0 }] } } }
plane { y, 0 pigment { average pigment_map { [1 rgb 1] [3 rgb 0] } } })");
    const auto at = picks(*p.scene.objects[0]->texture->map, Vec3());
    ASSERT_EQ(at.size(), 2u);
    EXPECT_NEAR(at[0].second, 0.25, 1e-9);
    EXPECT_NEAR(p.scene.objects[1]->texture->pigment->at(Vec3()).rgb.r, 0.25, 1e-9);
}

TEST(TextureMaps, PigmentMapBodiesAndDeclaredMaps) {
    ParsedScene p(R"(
#declare CM = color_map { [0 rgb 0] [1 rgb <1, 0, 0>] }
#declare P = pigment { gradient x color_map { CM } }
#declare PM = pigment_map { [0 P scale 2] [1 rgb <0, 0, 1>] }
plane { y, 0 pigment { gradient y pigment_map { PM } } })");
    const Pigment& pig = *firstTexture(p).pigment;
    // y = 0: the first entry, gradient x scaled by 2 at x = 0.5.
    EXPECT_NEAR(pig.at(Vec3(0.5, 0, 0)).rgb.r, 0.25, 1e-9);
    // y = 0.5: halfway to blue.
    const Color c = pig.at(Vec3(0.5, 0.5, 0));
    EXPECT_NEAR(c.rgb.r, 0.125, 1e-9);
    EXPECT_NEAR(c.rgb.b, 0.5, 1e-9);
}

TEST(TextureMaps, NormalMapsAndSlopeMaps) {
    ParsedScene p(R"(
#declare NM = normal_map { [0 bumps 0.5] [1 dents 0.5] }
plane { y, 0 normal { gradient x normal_map { NM } scale 2 } }
plane { y, 0 normal { checker normal { bumps } normal { dents } } }
plane { y, 0 normal { gradient x slope_map { [0 <0, 1>] [1 <1, 1>] } } })");
    const Normal& mapped = *p.scene.objects[0]->texture->normal;
    EXPECT_EQ(mapped.mapMode, Normal::MapMode::Values);
    ASSERT_EQ(mapped.map.size(), 2u);
    const Normal& listed = *p.scene.objects[1]->texture->normal;
    EXPECT_EQ(listed.mapMode, Normal::MapMode::List);
    const Normal& sloped = *p.scene.objects[2]->texture->normal;
    ASSERT_EQ(sloped.slopeMap.size(), 2u);
    // Height and slope 1 at both ends: the straight line h = v.
    EXPECT_NEAR(sloped.slopeHeight(0.3), 0.3, 1e-12);
    const Vec3 n = mapped.perturb(Vec3(0.7, 0, 0.2), Vec3(0, 1, 0));
    EXPECT_NEAR(length(n), 1.0, 1e-9);
}

TEST(TextureMaps, Errors) {
    EXPECT_NE(
        parseErrorOf("plane { y, 0 texture { checker texture { } texture { } pigment { rgb 1 } } }")
            .find("not allowed in a patterned texture"),
        std::string::npos);
    EXPECT_NE(parseErrorOf("#declare CM = color_map { [0 rgb 1] }\n"
                           "plane { y, 0 pigment { gradient x pigment_map { CM } } }")
                  .find("not a pigment_map"),
              std::string::npos);
    // povray 3.7 refuses patterned textures in layers, the lower one first.
    EXPECT_NE(parseErrorOf("plane { y, 0 texture { pigment { rgb 1 } } "
                           "texture { checker texture { } texture { } } }")
                  .find("Cannot layer a patterned texture over another."),
              std::string::npos);
    EXPECT_NE(parseErrorOf("plane { y, 0 texture { checker texture { } texture { } } "
                           "texture { gradient x texture_map { [0 pigment { rgb 1 }] } } }")
                  .find("Cannot layer over a patterned texture."),
              std::string::npos);
    EXPECT_NE(parseErrorOf("plane { y, 0 texture { material_map { png \"no_such.png\" } } }")
                  .find("material_map needs at least one texture"),
              std::string::npos);
}

TEST(TextureMaps, DeclaredNormals) {
    ParsedScene p(R"(
#declare N_Bumps = normal { bumps 0.4 scale 0.2 }
#declare N_Dents = normal { dents 0.4 }
plane { y, 0 normal { N_Bumps } }
plane { y, 0 normal { gradient x normal_map { [0 N_Bumps] [1 N_Dents] } } }
plane { y, 0 texture { normal { N_Bumps bump_size 0.8 } } })");
    const Normal& plain = *p.scene.objects[0]->texture->normal;
    EXPECT_EQ(plain.pattern.kind, PatternKind::Bumps);
    EXPECT_DOUBLE_EQ(plain.amount, 0.4);
    const Normal& mapped = *p.scene.objects[1]->texture->normal;
    ASSERT_EQ(mapped.map.size(), 2u);
    EXPECT_EQ(mapped.map[0].normal->pattern.kind, PatternKind::Bumps);
    EXPECT_EQ(mapped.map[1].normal->pattern.kind, PatternKind::Dents);
    EXPECT_DOUBLE_EQ(p.scene.objects[2]->texture->normal->amount, 0.8);
    // An empty normal is no normal_map entry (povray: "No normal type given").
    EXPECT_NE(parseErrorOf("#declare N = normal { }\n"
                           "plane { y, 0 normal { gradient x normal_map { [0 N] [1 bumps] } } }")
                  .find("needs a normal pattern"),
              std::string::npos);
}
