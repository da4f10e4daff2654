// prism { [linear_sweep | conic_sweep] [spline kind] h1, h2, N, points
// [open] } (seed 000 §3.4): closed plane outlines in x-z, made of spline
// pieces, swept along y from h1 to h2 — straight up (linear_sweep) or
// scaled by the height towards the origin (conic_sweep: the outline as
// given lies at y = 1). Capped at both heights unless `open`.
#pragma once

#include <vector>

#include "scene/shapes.h"
#include "scene/spline_profile.h"

namespace frameray::scene {

class Prism final : public Shape {
  public:
    // The outline pieces of all sub-shapes (see outlineOf); h1 != h2.
    Prism(std::vector<ProfileSegment> outline, double h1, double h2, bool conic, bool open);
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    Vec3 normal(const Vec3& p) const override;
    bool inside(const Vec3& p) const override;
    Bounds bounds() const override { return bounds_; }
    const char* name() const override { return "prism"; }

    // povray's reading of a prism's point list: sub-shapes follow each
    // other, each ending where its first point on the curve comes back.
    // `unclosed` tells whether the last one never came back (it is closed
    // by a straight piece for linear splines).
    static std::vector<ProfileSegment> outlineOf(SplineKind kind,
                                                 const std::vector<ProfilePoint>& points,
                                                 bool& unclosed);

  private:
    // Even-odd test of the outline at (x, z) (at y = 1 for conic sweeps).
    bool insideOutline(double x, double z) const;
    // Nearest outline piece and parameter to (x, z); squared distance.
    double closestPiece(double x, double z, const ProfileSegment*& seg, double& s) const;

    std::vector<ProfileSegment> outline_;
    double h1_, h2_;
    bool conic_, open_;
    Bounds bounds_;
};

}  // namespace frameray::scene
