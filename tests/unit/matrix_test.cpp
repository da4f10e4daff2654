#include <gtest/gtest.h>

#include "util/matrix.h"

using namespace frameray;

namespace {
void expectNear(const Vec3& a, const Vec3& b, double eps = 1e-12) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}
}  // namespace

TEST(Transform, RotateZTurnsXIntoY) {
    // POV-Ray's left-handed sense: rotate z*90 maps +x to +y.
    expectNear(Transform::rotate({0, 0, 90}).point({1, 0, 0}), {0, 1, 0});
    expectNear(Transform::rotate({90, 0, 0}).point({0, 1, 0}), {0, 0, 1});
    expectNear(Transform::rotate({0, 90, 0}).point({0, 0, 1}), {1, 0, 0});
}

TEST(Transform, RotationOrderIsXThenYThenZ) {
    const Vec3 p{1, 2, 3};
    const Vec3 stepwise = Transform::rotate({0, 0, 30}).point(
        Transform::rotate({0, 20, 0}).point(Transform::rotate({10, 0, 0}).point(p)));
    expectNear(Transform::rotate({10, 20, 30}).point(p), stepwise);
}

TEST(Transform, ThenComposesInOrderAndInverts) {
    const Transform t = Transform::scale({2, 3, 4}).then(Transform::translate({1, 0, 0}));
    expectNear(t.point({1, 1, 1}), {3, 3, 4});
    expectNear(t.inversePoint({3, 3, 4}), {1, 1, 1});
}

TEST(Transform, NormalsUseInverseTranspose) {
    // A plane y=x scaled by 2 in x: its normal must stay perpendicular.
    const Transform t = Transform::scale({2, 1, 1});
    const Vec3 n = normalize(t.normal({1, -1, 0}));
    const Vec3 tangent = t.direction({1, 1, 0});
    EXPECT_NEAR(dot(n, tangent), 0.0, 1e-12);
}

TEST(Matrix4, InverseOfShear) {
    Transform t;
    ASSERT_TRUE(Transform::fromMatrix(Matrix4::fromPovMatrix({1, 0, 0, 0.5, 1, 0, 0, 0, 1, 0, 0, 0}), t));
    expectNear(t.inversePoint(t.point({0.3, 0.7, -2})), {0.3, 0.7, -2});
    Transform singular;
    EXPECT_FALSE(Transform::fromMatrix(Matrix4::fromPovMatrix({1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0}), singular));
}
