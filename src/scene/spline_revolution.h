// Surfaces of revolution about the y axis from a plane profile:
// lathe { spline points } turns a spline curve in (radius, height)
// around the axis; sor { points } turns r^2 = cubic(h) pieces, closed by
// flat caps unless `open` (seed 000 §3.4: lathe, sor).
#pragma once

#include <vector>

#include "scene/shapes.h"
#include "scene/spline_profile.h"

namespace frameray::scene {

class Lathe final : public Shape {
  public:
    // `points` as the SDL lists them: <radius, height>; enough of them
    // for `kind` (and a multiple of 4 for bezier) is the caller's check.
    Lathe(SplineKind kind, const std::vector<ProfilePoint>& points);
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    Vec3 normal(const Vec3& p) const override;
    bool inside(const Vec3& p) const override;
    Bounds bounds() const override { return bounds_; }
    const char* name() const override { return "lathe"; }
    bool uv(const Vec3& p, double& u, double& v) const override;

  private:
    std::vector<ProfileSegment> segments_;
    Bounds bounds_;
};

class Sor final : public Shape {
  public:
    // At least 4 points with strictly increasing heights are the
    // caller's check.
    Sor(const std::vector<ProfilePoint>& points, bool open);
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    Vec3 normal(const Vec3& p) const override;
    bool inside(const Vec3& p) const override;
    Bounds bounds() const override { return bounds_; }
    const char* name() const override { return "sor"; }
    bool uv(const Vec3& p, double& u, double& v) const override;

  private:
    // r^2 over one height range: c[0] + c[1] s + c[2] s^2 + c[3] s^3 with
    // s = (h - h0) / (h1 - h0).
    struct Piece {
        double h0, h1;
        double c[4];
        double r2Max;
    };
    const Piece* pieceAt(double h) const;
    double radius2At(const Piece& piece, double h) const;

    std::vector<Piece> pieces_;
    bool open_;
    double bottom_, top_;      // heights of the caps
    double bottomR2_, topR2_;  // their squared radii
    Bounds bounds_;
};

}  // namespace frameray::scene
