// blob { threshold T  sphere { C, R, [strength] S }  cylinder { A, B, R, S }
//        component S, R, C ... [sturm] [hierarchy] }  (seed 003 §5.2.3.1).
//
// Each component spreads a field strength * (1 - d²/R²)² over the points at
// distance d < R from its centre (sphere) or from its axis segment
// (cylinder: a capsule, hemispherical at both ends), as povray 3.7 does;
// the surface is where the summed field equals the threshold, the inside
// where it exceeds it. A component may carry its own transformation, so its
// field region is an ellipsoid or a sheared capsule.
//
// Along a ray every component's d² is piecewise quadratic in the ray
// parameter, so the field is a piecewise quartic: the ray is cut where any
// component's support (or a cylinder's piece) starts or ends, and the
// quartic summed over each piece is solved on that piece alone.
#pragma once

#include <vector>

#include "scene/hit_tolerance.h"
#include "scene/shapes.h"

namespace frameray::scene {

class Blob final : public Shape {
  public:
    struct Component {
        enum class Kind { Sphere, Cylinder };
        Kind kind = Kind::Sphere;
        Vec3 a;  // the centre, or the first end of the axis
        Vec3 b;  // the other end of the axis (cylinder)
        double radius = 1;
        double strength = 1;
        bool transformed = false;
        Transform toBlob;  // component space -> blob space, when transformed

        // The field this component contributes at a point in blob space.
        double field(const Vec3& p) const;
        // Its gradient, in blob space.
        Vec3 gradient(const Vec3& p) const;
        // Blob-space box outside which the field is zero.
        Bounds bounds() const;
    };

    Blob(std::vector<Component> components, double threshold, bool sturm);

    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    double depthTolerance() const override { return kBlobDepthTolerance; }
    Vec3 normal(const Vec3& p) const override;
    bool inside(const Vec3& p) const override { return density(p) > threshold_; }
    Bounds bounds() const override { return bounds_; }
    Bounds insideBounds() const override { return bounds_; }
    const char* name() const override { return "blob"; }

    double density(const Vec3& p) const;
    double threshold() const { return threshold_; }
    bool sturm() const { return sturm_; }
    const std::vector<Component>& components() const { return components_; }
    Blob withSturm(bool sturm) const;

  private:
    std::vector<Component> components_;
    double threshold_;
    bool sturm_;
    Bounds bounds_;
};

}  // namespace frameray::scene
