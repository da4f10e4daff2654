// Compact storage of the values a scene holds by the million (issue 23):
// plain pigments without their pattern part, textures sharing their
// finish, pigment and transformations, objects holding their transform by
// reference, and the default texture shared by the objects placed under
// #default.
#include <gtest/gtest.h>

#include <cmath>

#include "parse_support.h"
#include "scene/object.h"
#include "util/shared_transform.h"
#include "util/value_box.h"

using namespace frameray;
using namespace frameray::scene;
using test_support::ParsedScene;

// The sizes 10^6 spheres each with its own colour pay for (before: Object
// 496, Texture 832, Pigment 976 bytes; 2548 MiB against povray's 1014).
TEST(CompactStorage, SizesOfTheValuesEveryObjectCarries) {
    EXPECT_LE(sizeof(Pigment), 64u);
    EXPECT_LE(sizeof(Texture), 160u);
    EXPECT_LE(sizeof(Object), 288u);
    EXPECT_EQ(sizeof(SharedTransform), 16u);
}

TEST(CompactStorage, SharedTransformKeepsTheIdentityWithoutAllocating) {
    const SharedTransform a;
    const SharedTransform b = Transform();
    EXPECT_EQ(&a.get(), &b.get());  // the one shared identity
    EXPECT_TRUE(a.isIdentity());
    const SharedTransform moved = Transform::translate({1, 2, 3});
    EXPECT_NE(&moved.get(), &a.get());
    EXPECT_DOUBLE_EQ(moved.point({0, 0, 0}).y, 2);
    EXPECT_DOUBLE_EQ(moved.inversePoint({1, 2, 3}).z, 0);
    const SharedTransform copy = moved;
    EXPECT_EQ(&copy.get(), &moved.get());  // copies share
}

TEST(CompactStorage, SharedTransformKeepsAnIdentityWithANegativeZero) {
    // A -0 entry compares equal to the identity's 0, yet products with it
    // may differ in the sign of zero: such a transform is kept as it is.
    Matrix4 m = Matrix4::identity();
    m.m[1][0] = -0.0;
    const SharedTransform s = Transform(m, m);
    EXPECT_NE(&s.get(), &SharedTransform().get());
    EXPECT_TRUE(std::signbit(s.matrix().m[1][0]));
    // So is one whose inverse is not exactly the identity's.
    Matrix4 inv = Matrix4::identity();
    inv.m[0][0] = 1.0 + 1e-16 * 2;
    const SharedTransform t = Transform(Matrix4::identity(), inv);
    EXPECT_NE(&t.get(), &SharedTransform().get());
}

TEST(CompactStorage, ValueBoxCopiesDeeplyAndReadsEmptyAsDefault) {
    ValueBox<std::vector<int>> a;
    EXPECT_FALSE(a.holds());
    EXPECT_TRUE(a.get().empty());
    a.edit().push_back(3);
    ValueBox<std::vector<int>> b = a;
    b.edit().push_back(4);
    EXPECT_EQ(a.get().size(), 1u);
    EXPECT_EQ(b.get().size(), 2u);
}

TEST(CompactStorage, PlainColourPigmentHasNoPatternPart) {
    ParsedScene p(R"(
sphere { 0, 1 pigment { color rgb <0.2, 0.5, 1> } }
sphere { 0, 1 pigment { rgb 1 turbulence 0.5 } }
sphere { 0, 1 pigment { color rgb 1 scale 2 } }
sphere { 0, 1 pigment { checker rgb 1 rgb 0 } }
sphere { 0, 1 pigment { color rgb 1 quick_color rgb 0.5 } })");
    const auto& o = p.scene.objects;
    ASSERT_EQ(o.size(), 5u);
    const Pigment& plain = *o[0]->texture->pigment;
    EXPECT_TRUE(plain.isSolid());
    EXPECT_FALSE(plain.hasPatternPart());
    EXPECT_DOUBLE_EQ(plain.at({3, 4, 5}).rgb.g, 0.5);
    EXPECT_FALSE(plain.quickColor().has_value());
    EXPECT_TRUE(plain.list().empty());
    // Whatever goes beyond the colour is kept.
    EXPECT_TRUE(o[1]->texture->pigment->pattern().turbulence.has_value());
    EXPECT_TRUE(o[2]->texture->pigment->hasPatternPart());
    EXPECT_EQ(o[3]->texture->pigment->kind(), Pigment::Kind::List);
    EXPECT_DOUBLE_EQ(o[3]->texture->pigment->at({0.5, 0.5, 0.5}).rgb.r, 1.0);
    ASSERT_TRUE(o[4]->texture->pigment->quickColor().has_value());
    EXPECT_DOUBLE_EQ(o[4]->texture->pigment->quickColor()->rgb.r, 0.5);
}

TEST(CompactStorage, TexturesShareTheDefaultFinishAndTheirDeclaredOnes) {
    ParsedScene p(R"(
#declare F = finish { phong 1 }
sphere { 0, 1 pigment { rgb 1 } }
sphere { 0, 1 pigment { rgb 0.5 } }
sphere { 0, 1 finish { F } }
sphere { 0, 1 finish { F } })");
    const auto& o = p.scene.objects;
    ASSERT_EQ(o.size(), 4u);
    EXPECT_EQ(o[0]->texture->finish.get(), o[1]->texture->finish.get());
    EXPECT_EQ(o[0]->texture->finish.get(), defaultFinish().get());
    EXPECT_DOUBLE_EQ(o[0]->texture->finish->diffuse, 0.6);
    EXPECT_DOUBLE_EQ(o[2]->texture->finish->phong, 1.0);
    EXPECT_EQ(o[0]->texture->transform.get().isIdentity(), true);
    EXPECT_EQ(&o[0]->texture->transform.get(), &o[1]->texture->transform.get());
}

TEST(CompactStorage, ObjectsUnderDefaultShareOneTexture) {
    ParsedScene p(R"(
#default { pigment { rgb <1, 0, 0> } }
sphere { 0, 1 }
sphere { 1, 1 }
#default { finish { phong 1 } }
sphere { 2, 1 })");
    const auto& o = p.scene.objects;
    ASSERT_EQ(o.size(), 3u);
    ASSERT_TRUE(o[0]->texture && o[2]->texture);
    EXPECT_EQ(o[0]->texture.get(), o[1]->texture.get());
    EXPECT_NE(o[0]->texture.get(), o[2]->texture.get());
    EXPECT_DOUBLE_EQ(o[0]->texture->finish->phong, 0.0);
    EXPECT_DOUBLE_EQ(o[2]->texture->finish->phong, 1.0);
    EXPECT_DOUBLE_EQ(o[2]->texture->pigment->solidColor().rgb.r, 1.0);
}
