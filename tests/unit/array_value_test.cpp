// ArrayValue: float elements kept unboxed, other kinds as Values, and the
// switch between the two (issue 23: an array[16777216] of floats costs
// 8 bytes an element, as in povray).
#include <gtest/gtest.h>

#include "sdl/value.h"

using namespace frameray::sdl;

TEST(ArrayValue, FloatsAreStoredAndReadBack) {
    ArrayValue a;
    a.reset(5);
    EXPECT_EQ(a.size(), 5u);
    EXPECT_EQ(a.kind(), nullptr);
    EXPECT_FALSE(a.isSet(2));
    EXPECT_TRUE(std::holds_alternative<std::monostate>(a.get(2)));
    a.set(2, 1.5);
    a.set(4, -3.0);
    EXPECT_STREQ(a.kind(), "float");
    EXPECT_TRUE(a.isSet(2));
    EXPECT_FALSE(a.isSet(3));
    EXPECT_EQ(std::get<double>(a.get(2)), 1.5);
    EXPECT_EQ(std::get<double>(a.get(4)), -3.0);
    EXPECT_EQ(std::get<double>(a.firstSet()), 1.5);
    EXPECT_TRUE(std::holds_alternative<std::monostate>(a.get(0)));
}

TEST(ArrayValue, OtherKindsAreValues) {
    ArrayValue a;
    a.reset(3);
    a.set(1, VectorValue::fromVec3({1, 2, 3}));
    EXPECT_STREQ(a.kind(), "vector");
    EXPECT_TRUE(a.isSet(1));
    EXPECT_FALSE(a.isSet(0));
    EXPECT_EQ(std::get<VectorValue>(a.get(1)).v[2], 3.0);
    EXPECT_EQ(std::get<VectorValue>(a.firstSet()).v[0], 1.0);
}

TEST(ArrayValue, CopiesAreIndependentAndUnsetWorks) {
    ArrayValue a;
    a.reset(4);
    a.set(0, 2.0);
    ArrayValue b = a;
    b.set(0, 7.0);
    EXPECT_EQ(std::get<double>(a.get(0)), 2.0);
    EXPECT_EQ(std::get<double>(b.get(0)), 7.0);
    b.set(0, Value{});
    EXPECT_FALSE(b.isSet(0));
    EXPECT_TRUE(std::holds_alternative<std::monostate>(b.firstSet()));
}

TEST(ArrayValue, ArraysOfArraysTellTheirInnermostKind) {
    auto inner = std::make_shared<ArrayValue>();
    inner->reset(2);
    inner->set(1, 4.0);
    auto outer = std::make_shared<ArrayValue>();
    outer->reset(2);
    outer->set(0, ArrayPtr(inner));
    EXPECT_STREQ(outer->kind(), "array");
    EXPECT_TRUE(arrayHolds<double>(Value(ArrayPtr(outer))));
    EXPECT_FALSE(arrayHolds<std::string>(Value(ArrayPtr(outer))));
}
