// polygon { N, points }: a flat patch bounded by one or more closed loops
// of points, filled by the even-odd rule (a loop inside another is a hole).
#pragma once

#include <array>
#include <vector>

#include "scene/shapes.h"

namespace frameray::scene {

class Polygon final : public Shape {
  public:
    // Each loop lists its corners once (not repeating the first at the end).
    // The plane is the points' best fit by Newell's method; points off it
    // are projected onto it.
    explicit Polygon(const std::vector<std::vector<Vec3>>& loops);
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    bool firstHit(const Ray& ray, double tMin, double tMax, double& t) const override;
    Vec3 normal(const Vec3&) const override { return normal_; }
    bool inside(const Vec3&) const override { return false; }
    bool isPatch() const override { return true; }
    Bounds bounds() const override { return bounds_; }
    Bounds insideBounds() const override { return {}; }
    const char* name() const override { return "polygon"; }
    // Whether the points span no plane (all in one line): never hit.
    bool isDegenerate() const { return degenerate_; }

  private:
    // Whether the plane point with coordinates (u, v) lies inside.
    bool contains(double u, double v) const;

    Vec3 origin_, normal_, axisU_, axisV_;
    std::vector<std::array<double, 4>> edges_;  // u0, v0, u1, v1 in plane coordinates
    Bounds bounds_;
    bool degenerate_ = false;
};

}  // namespace frameray::scene
