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
// Rays march through the bounding sphere (radius R) in steps of
// 1 / precision and refine each crossing by bisection, so features
// thinner than a step may be missed, as povray misses them (not at the
// same places: povray's marching is not reproduced exactly).
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
    double stepLength_;
    double radius_, radius2_;
};

}  // namespace frameray::scene
