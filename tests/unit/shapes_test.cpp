#include "scene/shapes.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace frameray;
using namespace frameray::scene;

TEST(Sphere, HitsAndInside) {
    Sphere s({0, 0, 5}, 1);
    double t;
    ASSERT_TRUE(s.firstHit({{0, 0, 0}, {0, 0, 1}}, 0, kInfinity, t));
    EXPECT_DOUBLE_EQ(t, 4);
    std::vector<double> ts;
    s.allHits({{0, 0, 0}, {0, 0, 2}}, 0, kInfinity, ts);  // unnormalised direction
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_DOUBLE_EQ(ts[0], 2);
    EXPECT_DOUBLE_EQ(ts[1], 3);
    EXPECT_TRUE(s.inside({0, 0, 5.5}));
    EXPECT_FALSE(s.inside({0, 0, 6.5}));
    EXPECT_FALSE(s.firstHit({{0, 2, 0}, {0, 0, 1}}, 0, kInfinity, t));
}

TEST(Sphere, FarAwayRayKeepsPrecision) {
    // A unit sphere seen from 1e8 units: the hit must still be on the surface.
    Sphere s({0, 0, 0}, 1);
    double t;
    ASSERT_TRUE(s.firstHit({{0.5, 0, -1e8}, {0, 0, 1}}, 0, kInfinity, t));
    const double z = -1e8 + t;
    EXPECT_NEAR(0.25 + z * z, 1.0, 1e-7);
}

TEST(Plane, DistanceIsAlongTheNormalisedNormal) {
    Plane p({0, 2, 0}, 1);  // povray 3.7 puts this plane at y = 1
    double t;
    ASSERT_TRUE(p.firstHit({{0, 5, 0}, {0, -1, 0}}, 0, kInfinity, t));
    EXPECT_DOUBLE_EQ(t, 4);
    EXPECT_TRUE(p.inside({0, 0, 0}));
}

TEST(Box, SlabsAndNormals) {
    Box b({1, 1, 1}, {-1, -1, -1});
    double t;
    ASSERT_TRUE(b.firstHit({{0, 0, -5}, {0, 0, 1}}, 0, kInfinity, t));
    EXPECT_DOUBLE_EQ(t, 4);
    const Vec3 n = b.normal({0.2, 0.3, -1});
    EXPECT_EQ(n.z, -1);
    EXPECT_TRUE(b.inside({0.9, 0, 0}));
    EXPECT_FALSE(b.inside({1.1, 0, 0}));
    EXPECT_FALSE(b.firstHit({{2, 0, -5}, {0, 0, 1}}, 0, kInfinity, t));
}

TEST(Box, FlatBoxNormalIsItsFaceWhateverTheRounding) {
    // var_reflection.pov's boxes <-1,-5,0.25>,<1,20000,0.25>: a hit point a
    // rounding error off z = 0.25 still lies on the flat face (povray
    // reflects off all of it).
    Box b({-1, -5, 0.25}, {1, 20000, 0.25});
    for (const double dz : {0.0, 1e-16, -1e-16, 5.55e-17}) {
        const Vec3 n = b.normal({0.99, 19999.9, 0.25 + dz});
        EXPECT_EQ(std::fabs(n.z), 1) << dz;
        EXPECT_EQ(n.x, 0) << dz;
        EXPECT_EQ(n.y, 0) << dz;
    }
}
