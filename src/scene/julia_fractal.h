// julia_fractal { <c> quaternion|hypercomplex sqr|cube max_iteration N
// precision P }: the 3-D slice w = 0 of a 4-D Julia set, as povray 3.7
// renders it (measured with trace() on its surface points and normals):
//   - a point p = (x, y, z, 0) is inside when the iterates q0 = p,
//     q(k+1) = f(q(k)) + c stay within the bailout radius for k = 0 ..
//     N - 1 (|q(k)|^2 <= R^2; q(N) itself is not tested);
//   - R = 1 + |c| for quaternions, 4 for hypercomplex numbers;
//   - f squares or cubes the quaternion; hypercomplex numbers square each
//     of their two complex components, (x - w) + (y + z) i and
//     (x + w) + (y - z) i;
//   - the surface normal is the gradient of |q(N)|^2, pointing outwards.
// Rays march as povray 3.7's do (documented facts of its algorithm,
// reimplemented): from where the ray enters the bounding sphere (radius
// R; quaternions: min(1 + |c| + 1e-7, 2), bailout R^2 + 1e-7;
// hypercomplex: 4 and 16), each step as long as a distance estimate at the
// current point allows but at least 1 / precision; a change between
// inside and outside is refined by bisection down to 1e-7, the hit being
// the inside end of the last bracket. The estimates:
//   - quaternion sqr (cube): a point escaping at iterate k has
//     2^-(k+1) (3^-(k+1)) ln|q(k)|^2 / |q(0)| ... |q(k-1)|;
//   - hypercomplex sqr: |q(k)|^2 / (2 g) when g, minus the component
//     along the ray of povray's gradient at iterate k (built from
//     q(0) ... q(k-1) and 2^k q(k)), is positive and the result lies
//     between 1 and 30 steps; otherwise one step;
//   - a point inside: one step.
// A ray starting inside the set first moves 2e-7 on. Thin features are
// thus missed exactly where povray misses them. Without CSG povray stops
// at the first crossing; so does firstHit().
#pragma once

#include <array>

#include "scene/shapes.h"

namespace frameray::scene {

class JuliaFractal final : public Shape {
  public:
    enum class Algebra { Quaternion, Hypercomplex };
    enum class Function { Sqr, Cube };

    JuliaFractal(const std::array<double, 4>& c, Algebra algebra, Function function,
                 int maxIterations, double precision);
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    bool firstHit(const Ray& ray, double tMin, double tMax, double& t) const override;
    Vec3 normal(const Vec3& p) const override;
    bool inside(const Vec3& p) const override;
    Bounds bounds() const override { return {Vec3(-radius_), Vec3(radius_)}; }
    const char* name() const override { return "julia_fractal"; }

  private:
    using Quat = std::array<double, 4>;
    Quat step(const Quat& q) const;  // f(q) + c
    // Whether p is inside; `step` gets the march step povray takes from p
    // along the unit direction u (see above).
    bool probe(const Vec3& p, const Vec3& u, double& step) const;
    // |q(N)|^2 after every iteration (no bailout): the normal's potential.
    double potential(const Vec3& p) const;
    // Calls crossing(t) for the crossings along the ray within (tMin,
    // tMax), in order, while it returns true.
    template <typename Crossing>
    void march(const Ray& ray, double tMin, double tMax, Crossing&& crossing) const;

    Quat c_;
    Algebra algebra_;
    Function function_;
    int maxIterations_;
    double stepLength_;  // 1 / precision
    double radius_, radius2_;
    double bailout2_;  // |q|^2 above this escapes
};

}  // namespace frameray::scene
