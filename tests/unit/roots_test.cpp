// Root solvers (util/roots.h): exact roots, multiple and clustered roots,
// roots far apart in magnitude, cancellation-prone coefficients, and
// randomized property tests against a long-double reference.
#include "util/roots.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace frameray {
namespace {

// Coefficients (increasing power) of lead * prod (x - r_i), expanded in long
// double and rounded once.
std::vector<double> fromRoots(const std::vector<double>& rs, double lead = 1) {
    std::vector<long double> c{static_cast<long double>(lead)};
    for (double r : rs) {
        std::vector<long double> next(c.size() + 1, 0);
        for (std::size_t i = 0; i < c.size(); ++i) {
            next[i + 1] += c[i];
            next[i] -= c[i] * r;
        }
        c = next;
    }
    return {c.begin(), c.end()};
}

// The root of the double-coefficient polynomial near `guess`, by Newton's
// method in long double: the reference the solvers must reproduce.
long double referenceRoot(const std::vector<double>& c, long double x) {
    for (int i = 0; i < 60; ++i) {
        long double v = 0, s = 0;
        for (std::size_t k = c.size(); k-- > 0;) {
            s = s * x + v;
            v = v * x + c[k];
        }
        if (v == 0 || s == 0) break;
        const long double next = x - v / s;
        if (next == x) break;
        x = next;
    }
    return x;
}

std::vector<double> solve(const std::vector<double>& c, RootMethod method, double lo = -1e300,
                          double hi = 1e300) {
    std::vector<double> out(c.size());
    const int n = realRootsInInterval(c, lo, hi, out.data(), method);
    out.resize(n);
    return out;
}

void expectRoots(const std::vector<double>& got, const std::vector<double>& want, double relTol,
                 const char* what) {
    ASSERT_EQ(got.size(), want.size()) << what;
    for (std::size_t i = 0; i < want.size(); ++i)
        EXPECT_NEAR(got[i], want[i], relTol * std::max(1e-300, std::fabs(want[i])))
            << what << " root " << i;
}

const RootMethod kMethods[] = {RootMethod::ClosedForm, RootMethod::Sturm};
const char* methodName(RootMethod m) {
    return m == RootMethod::Sturm ? "sturm" : "closed form";
}

TEST(Roots, EvaluatesWithHorner) {
    const std::vector<double> c{1, -3, 0, 2};  // 2x³ - 3x + 1
    EXPECT_DOUBLE_EQ(evaluatePolynomial(c, 2), 11);
    double v, s;
    evaluatePolynomialAndSlope(c, 2, v, s);
    EXPECT_DOUBLE_EQ(v, 11);
    EXPECT_DOUBLE_EQ(s, 21);
}

TEST(Roots, QuadraticExact) {
    double r[2];
    ASSERT_EQ(solveQuadratic(6, -5, 1, r), 2);
    EXPECT_DOUBLE_EQ(r[0], 2);
    EXPECT_DOUBLE_EQ(r[1], 3);
    EXPECT_EQ(solveQuadratic(1, 0, 1, r), 0);
    ASSERT_EQ(solveQuadratic(1, -2, 1, r), 1);  // double root reported once
    EXPECT_DOUBLE_EQ(r[0], 1);
    ASSERT_EQ(solveQuadratic(4, 2, 0, r), 1);  // linear
    EXPECT_DOUBLE_EQ(r[0], -2);
}

TEST(Roots, QuadraticKeepsTinyRootNextToHugeOne) {
    // (x - 1e-8)(x - 1e8): the naive formula loses the small root entirely.
    double r[2];
    ASSERT_EQ(solveQuadratic(1, -(1e8 + 1e-8), 1, r), 2);
    EXPECT_NEAR(r[0], 1e-8, 1e-22);
    EXPECT_NEAR(r[1], 1e8, 1e-6);
}

TEST(Roots, CubicAndQuarticExact) {
    for (RootMethod m : kMethods) {
        expectRoots(solve(fromRoots({-2, 1, 3}), m), {-2, 1, 3}, 1e-14, methodName(m));
        expectRoots(solve(fromRoots({-3, -1, 0.5, 4}), m), {-3, -1, 0.5, 4}, 1e-14, methodName(m));
        // One real root and a complex pair: (x - 2)(x² + 1).
        expectRoots(solve({-2, 1, -2, 1}, m), {2}, 1e-14, methodName(m));
        // No real roots: (x² + 1)(x² + 4).
        expectRoots(solve({4, 0, 5, 0, 1}, m), {}, 0, methodName(m));
        // Biquadratic: (x² - 1)(x² - 4).
        expectRoots(solve({4, 0, -5, 0, 1}, m), {-2, -1, 1, 2}, 1e-14, methodName(m));
    }
}

TEST(Roots, TorusLikeQuartic) {
    // A ray along x through a torus of major radius 2, minor 0.5 centred at
    // the origin: (x² + R² - r²)² - 4R²x² = 0 has roots ±1.5, ±2.5.
    const double R2 = 4, r2 = 0.25;
    const double k = R2 - r2;
    const std::vector<double> c{k * k, 0, 2 * k - 4 * R2, 0, 1};
    for (RootMethod m : kMethods)
        expectRoots(solve(c, m), {-2.5, -1.5, 1.5, 2.5}, 1e-14, methodName(m));
}

TEST(Roots, DoubleRoots) {
    // A double root is a tangent: found once (or as a tight cluster by the
    // closed forms), to about sqrt(eps) since rounding the coefficients
    // moves it that much.
    for (RootMethod m : kMethods) {
        const auto got = solve(fromRoots({1, 1, 3}), m);
        ASSERT_GE(got.size(), 1u) << methodName(m);
        EXPECT_NEAR(got.front(), 1, 1e-7) << methodName(m);
        EXPECT_NEAR(got.back(), 3, 1e-13) << methodName(m);
        for (double r : got) EXPECT_TRUE(std::fabs(r - 1) < 1e-7 || std::fabs(r - 3) < 1e-13) << r;

        const auto two = solve(fromRoots({-1, -1, 2, 2}), m);
        ASSERT_GE(two.size(), 2u) << methodName(m);
        for (double r : two) EXPECT_TRUE(std::fabs(r + 1) < 1e-7 || std::fabs(r - 2) < 1e-7) << r;
    }
    // Sturm reports distinct roots exactly once.
    EXPECT_EQ(solve(fromRoots({1, 1, 3}), RootMethod::Sturm).size(), 2u);
    EXPECT_EQ(solve(fromRoots({-1, -1, 2, 2}), RootMethod::Sturm).size(), 2u);
    EXPECT_EQ(solve(fromRoots({0.5, 0.5, 0.5}), RootMethod::Sturm).size(), 1u);
}

TEST(Roots, NearDoubleRootsStaySeparate) {
    // Roots 1e-6 apart: each is well conditioned enough to resolve.
    for (RootMethod m : kMethods) {
        expectRoots(solve(fromRoots({1, 1 + 1e-6, 5}), m), {1, 1 + 1e-6, 5}, 1e-9, methodName(m));
        expectRoots(solve(fromRoots({-2, 1, 1 + 1e-6, 5}), m), {-2, 1, 1 + 1e-6, 5}, 1e-9,
                    methodName(m));
    }
}

TEST(Roots, WidelySeparatedMagnitudes) {
    for (RootMethod m : kMethods) {
        expectRoots(solve(fromRoots({1e-8, 1, 1e8}), m), {1e-8, 1, 1e8}, 1e-12, methodName(m));
        expectRoots(solve(fromRoots({-1e8, 1e-8, 1, 1e8}), m), {-1e8, 1e-8, 1, 1e8}, 1e-12,
                    methodName(m));
    }
}

TEST(Roots, CancellationProneCoefficients) {
    // A quartic whose roots cluster far from the origin (a torus seen from
    // far away before the ray is re-originated): roots 1000 + {0, 0.1,
    // 0.3, 0.6}. The coefficients cancel heavily: near the roots p(x) is
    // computed with an absolute error around 1e12 * eps = 1e-4 while
    // |p'| ~ 0.02, so no double-precision solver can do better than a few 1e-2.
    // All four must still be found (this is why shapes move the ray origin
    // next to the shape before solving).
    const std::vector<double> rs{1000, 1000.1, 1000.3, 1000.6};
    for (RootMethod m : kMethods) {
        const auto c = fromRoots(rs);
        const auto got = solve(c, m);
        ASSERT_EQ(got.size(), 4u) << methodName(m);
        for (int i = 0; i < 4; ++i)
            EXPECT_NEAR(got[i], static_cast<double>(referenceRoot(c, rs[i])), 0.1) << methodName(m);
    }
}

TEST(Roots, IntervalRestrictsRoots) {
    const auto c = fromRoots({-3, -1, 0.5, 4});
    for (RootMethod m : kMethods) {
        expectRoots(solve(c, m, 0, 10), {0.5, 4}, 1e-14, methodName(m));
        expectRoots(solve(c, m, -1.5, 0.75), {-1, 0.5}, 1e-14, methodName(m));
        expectRoots(solve(c, m, 5, 10), {}, 0, methodName(m));
    }
    double r[4];
    EXPECT_EQ(sturmRoots(c, -INFINITY, INFINITY, r), 4);
}

TEST(Roots, HighDegreeSturm) {
    // Degree 7 and degree 12 with known roots.
    const std::vector<double> r7{-3, -2, -0.5, 0.25, 1, 2.5, 6};
    expectRoots(solve(fromRoots(r7), RootMethod::ClosedForm), r7, 1e-11, "degree 7");
    std::vector<double> r12;
    for (int i = 0; i < 12; ++i) r12.push_back(-2.75 + 0.5 * i);
    expectRoots(solve(fromRoots(r12), RootMethod::Sturm), r12, 1e-8, "degree 12");
    // (x² + 1)^3 (x - 1): one real root.
    auto c = fromRoots({1});
    for (int i = 0; i < 3; ++i) {
        std::vector<double> next(c.size() + 2, 0);
        for (std::size_t k = 0; k < c.size(); ++k) {
            next[k] += c[k];
            next[k + 2] += c[k];
        }
        c = next;
    }
    expectRoots(solve(c, RootMethod::Sturm), {1}, 1e-13, "complex triples");
}

// Random polynomials with known real roots (and some complex pairs): every
// root the long-double reference finds is found, and nothing else.
TEST(Roots, PropertyAgainstLongDoubleReference) {
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (int degree = 2; degree <= 7; ++degree) {
        for (int trial = 0; trial < 400; ++trial) {
            std::vector<double> real;
            int complexPairs = 0;
            for (int k = 0; k < degree;) {
                if (degree - k >= 2 && uniform(rng) < -0.5) {
                    ++complexPairs;
                    k += 2;
                } else {
                    // Roots spread over magnitudes 1e-3 .. 1e3, at least 1e-3
                    // apart relatively so each is well conditioned.
                    real.push_back(std::copysign(std::pow(10.0, 3 * uniform(rng)), uniform(rng)));
                    ++k;
                }
            }
            std::sort(real.begin(), real.end());
            bool separated = true;
            for (std::size_t i = 1; i < real.size(); ++i)
                if (real[i] - real[i - 1] <
                    1e-2 * std::max(std::fabs(real[i]), std::fabs(real[i - 1])))
                    separated = false;
            if (!separated) continue;
            auto c = fromRoots(real, 0.5 + uniform(rng) * 0.25);
            for (int pair = 0; pair < complexPairs; ++pair) {
                // Multiply by (x - a)² + b², b well away from 0.
                const double a = 2 * uniform(rng), b = 0.5 + std::fabs(uniform(rng));
                std::vector<double> next(c.size() + 2, 0);
                for (std::size_t k = 0; k < c.size(); ++k) {
                    next[k] += c[k] * (a * a + b * b);
                    next[k + 1] -= c[k] * 2 * a;
                    next[k + 2] += c[k];
                }
                c = next;
            }
            for (RootMethod m : kMethods) {
                const auto got = solve(c, m);
                ASSERT_EQ(got.size(), real.size())
                    << methodName(m) << " degree " << degree << " trial " << trial;
                for (std::size_t i = 0; i < real.size(); ++i) {
                    const double want = static_cast<double>(referenceRoot(c, real[i]));
                    EXPECT_NEAR(got[i], want, 1e-9 * std::max(1.0, std::fabs(want)))
                        << methodName(m) << " degree " << degree << " trial " << trial;
                }
            }
        }
    }
}

}  // namespace
}  // namespace frameray
