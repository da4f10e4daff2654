// functions.inc's internal functions against values povray 3.7 prints for
// the same calls (#debug str(f(...), 0, 9)).
#include "scene/internal_functions.h"

#include <gtest/gtest.h>

#include <vector>

namespace frameray::scene {
namespace {

double call(int n, std::vector<double> args) {
    const InternalFunction f = internalFunction(n);
    EXPECT_TRUE(f.function) << f.name;
    EXPECT_EQ(static_cast<int>(args.size()), 3 + f.extraParams) << f.name;
    return f.function ? f.function->eval(args.data()) : 0.0;
}

constexpr int kEllipsoid = 17, kParaboloid = 45, kPh = 47, kR = 57, kRoundedBox = 60, kSphere = 61,
              kSuperellipsoid = 68, kTh = 69, kTorus = 70, kNoise3d = 76;

TEST(InternalFunctions, NamesAndParameterCountsFollowFunctionsInc) {
    EXPECT_EQ(internalFunction(kSphere).name, "f_sphere");
    EXPECT_EQ(internalFunction(kSphere).extraParams, 1);
    EXPECT_EQ(internalFunction(kRoundedBox).extraParams, 4);
    EXPECT_EQ(internalFunction(24).name, "f_helical_torus");
    EXPECT_EQ(internalFunction(24).extraParams, 10);
    EXPECT_TRUE(internalFunction(77).name.empty());  // no function 77
    EXPECT_TRUE(internalFunction(79).name.empty());
    EXPECT_TRUE(internalFunction(-1).name.empty());
}

TEST(InternalFunctions, DistanceFunctionsMatchPovray) {
    EXPECT_NEAR(call(kSphere, {0.3, 0.2, 0.1, 0.7}), -0.325834, 1e-6);
    EXPECT_NEAR(call(kR, {0.3, 0.2, 0.1}), 0.374166, 1e-6);
    EXPECT_NEAR(call(kTorus, {0.3, 0.2, 0.1, 1, 0.25}), 0.462421552, 1e-9);
    EXPECT_NEAR(call(kTorus, {1.7, -0.4, 2.2, 1, 0.25}), 1.574671064, 1e-9);
    EXPECT_NEAR(call(kRoundedBox, {0.3, 0.2, 0.1, 0.1, 0.5, 0.6, 0.7}), -0.100001, 1e-9);
    EXPECT_NEAR(call(kRoundedBox, {1.7, -0.4, 2.2, 0.1, 0.5, 0.6, 0.7}), 1.961551813, 1e-9);
    EXPECT_NEAR(call(kRoundedBox, {-0.6, 0.9, -1.3, 0.0, 0.5, 0.6, 0.7}), 0.678231998, 1e-9);
    EXPECT_NEAR(call(kEllipsoid, {-0.6, 0.9, -1.3, 1, 2, 3}), 4.337049688, 1e-9);
    EXPECT_NEAR(call(kSuperellipsoid, {0.3, 0.2, 0.1, 0.3, 0.6}), 0.694827624, 1e-9);
    EXPECT_NEAR(call(kSuperellipsoid, {1.7, -0.4, 2.2, 0.3, 0.6}), -1.445807742, 1e-9);
    EXPECT_NEAR(call(kSuperellipsoid, {0.05, 0.5, 0.77, 0.3, 0.6}), 0.179247652, 1e-9);
}

TEST(InternalFunctions, AnglesMatchPovray) {
    EXPECT_NEAR(call(kTh, {0.3, 0.2, 0.1}), 1.249045772, 1e-9);
    EXPECT_NEAR(call(kTh, {-0.6, 0.9, -1.3}), -2.709184878, 1e-9);
    EXPECT_NEAR(call(kPh, {1.7, -0.4, 2.2}), 1.713685841, 1e-9);
    EXPECT_EQ(call(kPh, {0, 0, 0}), 0.0);
    EXPECT_EQ(call(kTh, {0, 0, 0}), 0.0);
}

TEST(InternalFunctions, FieldStrengthSaturatesAtTen) {
    EXPECT_NEAR(call(kParaboloid, {-1.5, -2.5, 0, 1.5}), -7.125, 1e-12);
    EXPECT_NEAR(call(kParaboloid, {-1.5, -2.5, 0, -2}), 9.5, 1e-12);
    EXPECT_EQ(call(kParaboloid, {-1.5, -2.5, 0, -5}), 10.0);
    EXPECT_EQ(call(kParaboloid, {-1.5, -2.5, 0, 3}), -10.0);
}

TEST(InternalFunctions, NoiseIsBozoNoise) {
    EXPECT_NEAR(call(kNoise3d, {0.3, 0.2, 0.1}), 0.373439, 1e-6);
    EXPECT_NEAR(call(78, {0.3, 0.2, 0.1, 1}), 0.209925, 1e-6);
    EXPECT_NEAR(call(78, {0.3, 0.2, 0.1, 2}), 0.373439, 1e-6);
    EXPECT_THROW(call(78, {0.3, 0.2, 0.1, 3}), std::runtime_error);  // not supported yet
}

}  // namespace
}  // namespace frameray::scene
