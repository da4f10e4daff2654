// superellipsoid { <e, n> } (seed 000 §3.4.5): the surface
//     (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1
// inside the cube -1..1; e shapes the cross-sections parallel to the xy
// plane, n the ones through the z axis.
#pragma once

#include "scene/shapes.h"

namespace frameray::scene {

class Superellipsoid final : public Shape {
  public:
    // e, n > 0 are the caller's to check.
    Superellipsoid(double e, double n);
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    Vec3 normal(const Vec3& p) const override;
    bool inside(const Vec3& p) const override { return implicit(p) < 0; }
    Bounds bounds() const override { return {Vec3(-1), Vec3(1)}; }
    const char* name() const override { return "superellipsoid"; }

    // The implicit function: negative inside, zero on the surface.
    double implicit(const Vec3& p) const;

  private:
    double e_, n_;
    double xyPower_;     // 2 / e
    double zPower_;      // 2 / n
    double outerPower_;  // e / n
};

}  // namespace frameray::scene
