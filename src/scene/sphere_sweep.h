// sphere_sweep { linear_spline | b_spline | cubic_spline  N, <c>, r, ... }
// (seed 000 §3.4): the space a sphere covers while its centre and radius
// follow a spline through 4-D control points.
//
// Between two control points of a linear spline the swept sphere covers
// the two end balls and the truncated cone tangent to both, so the shape
// is a union of balls and cones whose boundary crossings are exact.
// Curved splines are followed by short linear pieces (kPiecesPerSegment
// per spline segment, hits within ~1e-4 of the segment's size of the
// exact envelope); their normals come from the exact spline: the
// direction from the nearest swept sphere's centre.
#pragma once

#include <optional>
#include <vector>

#include "scene/revolved_shapes.h"
#include "scene/shapes.h"

namespace frameray::scene {

enum class SweepSpline { Linear, BSpline, CatmullRom };

struct SweepPoint {
    Vec3 center;
    double radius = 0;
};

class SphereSweep final : public Shape {
  public:
    static constexpr int kPiecesPerSegment = 64;

    // Enough points for `kind` (2 linear, 4 otherwise) is the caller's
    // check.
    SphereSweep(SweepSpline kind, const std::vector<SweepPoint>& points);
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    Vec3 normal(const Vec3& p) const override;
    bool inside(const Vec3& p) const override;
    Bounds bounds() const override { return bounds_; }
    const char* name() const override { return "sphere_sweep"; }

    // The swept sphere at parameter s of spline segment `segment`.
    SweepPoint sphereAt(size_t segment, double s) const;
    size_t segmentCount() const { return segments_.size(); }

  private:
    // One spline segment: centre and radius as cubics in s (increasing
    // powers).
    struct Segment {
        Vec3 c[4];
        double r[4];
        Bounds box;  // of its pieces, to skip them together
        size_t firstPiece = 0, endPiece = 0;
    };
    // One linear piece: a ball at its start and the cone to the next ball
    // (cone absent when one ball holds the other).
    struct Piece {
        SweepPoint from, to;
        size_t segment;
        double s0, s1;             // its range of the spline parameter
        std::optional<Cone> cone;  // capped; its caps lie inside the balls
        Bounds box;
    };

    // Signed distance from p to the sphere of segment `seg` at s; the
    // least over s is the distance to the swept shape.
    double sweepDistance(const Vec3& p, size_t seg, double s) const;

    SweepSpline kind_;
    std::vector<Segment> segments_;
    std::vector<Piece> pieces_;
    SweepPoint last_;  // the ball at the very end
    Bounds bounds_;
};

}  // namespace frameray::scene
