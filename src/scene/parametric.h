// parametric { function { x(u, v) } function { y(u, v) } function { z(u, v) }
// <u1, v1>, <u2, v2> ... } (povray 3.7): the surface swept by the point
// (x, y, z)(u, v) over a rectangle of (u, v), clipped to a container box or
// sphere.
//
// A ray is met by subdividing the (u, v) rectangle: `max_gradient` bounds
// how fast each coordinate changes with u and v, so a piece of the
// rectangle lies in a box around the point at its centre; pieces whose box
// the ray misses are dropped, nearer boxes are searched first, and pieces
// smaller than `accuracy` are solved exactly for (u, v, t) by Newton's
// method. What povray 3.7 does that is matched here (measured):
//  - a ray reports only its first crossing inside the container, so CSG and
//    clipped_by see no surface behind a rejected one;
//  - it encloses nothing: its inside test is false even when inverted
//    (like a triangle, but without the "Patch objects" warning);
//  - the container defaults to box { -1, 1 }; precompute only speeds
//    povray up and changes nothing here.
// What is not matched: povray reports a point in front of the surface, on
// the box of its last sector (trace() on the plane function { u }
// function { v } function { 0 } along z gives z = -(accuracy +
// max_gradient (du + dv) / 2), du and dv the sector's size once below
// accuracy). Here hits are exact, so at a coarse accuracy povray's
// silhouettes and shadows are a little fatter (about 0.96-0.99 match on
// its Parametric_Surfaces templates at 160x120; 0.998 at the default
// accuracy 0.001).
#pragma once

#include <memory>

#include "scene/shapes.h"
#include "util/function_vm.h"

namespace frameray::scene {

struct ParametricSettings {
    // x, y and z as functions of u and v (the VM's first two parameters).
    std::shared_ptr<const CompiledFunction> fx, fy, fz;
    double uMin = 0, vMin = 0, uMax = 1, vMax = 1;
    bool sphereContainer = false;
    Vec3 boxLo{-1, -1, -1}, boxHi{1, 1, 1};
    Vec3 center;
    double radius = 1;
    double accuracy = 0.001;
    double maxGradient = 1;
};

class Parametric final : public Shape {
  public:
    explicit Parametric(ParametricSettings settings);
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    bool firstHit(const Ray& ray, double tMin, double tMax, double& t) const override;
    Vec3 normal(const Vec3& p) const override;
    bool inside(const Vec3&) const override { return false; }
    bool isPatch() const override { return true; }
    bool warnsAsPatch() const override { return false; }
    Bounds bounds() const override;
    const char* name() const override { return "parametric"; }

    // The surface point at (u, v).
    Vec3 point(double u, double v) const {
        const double args[3] = {u, v, 0};
        return {s_.fx->eval(args), s_.fy->eval(args), s_.fz->eval(args)};
    }
    // The (u, v) of the surface point nearest p; false when none is near.
    bool parametersOf(const Vec3& p, double& u, double& v) const;

  private:
    // A rectangle of (u, v), the surface points at its corners (p[i + 2 j]
    // at (u_i, v_j)) and middle (p[4], only down to kTreeDepth), its depth in the subdivision, the
    // box holding its piece of surface, its node in tree_ (-1: none) and,
    // while searching along a ray, the ray's entry into its box.
    struct Sector {
        double u0, u1, v0, v1;
        Vec3 p[5];
        int depth;
        double tNear;
        Vec3 lo, hi;
        int node = -1;
    };
    // The first levels of the subdivision, built once (povray's
    // `precompute` does the same for speed): every ray starts its search
    // there instead of evaluating the functions again.
    struct TreeNode {
        Sector sector;
        int firstChild = -1;
        int childCount = 0;
    };
    static constexpr int kTreeDepth = 6;
    // Deep enough for accuracy 1e-12 over a range of 1e3; deeper sectors
    // count as small enough.
    static constexpr int kMaxDepth = 56;

    // The whole rectangle, with boxes grown by `gradient`.
    Sector rootSector(double gradient) const;
    // Splits a sector in halves along u and/or v (those longer than
    // `accuracy`) into `kids`, with boxes grown by `gradient`; 0 when it is
    // small enough to solve. Taken from tree_ where it can be.
    int split(const Sector& s, double gradient, Sector* kids) const;
    void buildTree();
    void sectorBox(const Sector& s, double gradient, Vec3& lo, Vec3& hi) const;
    // parametersOf with sector boxes grown by `gradient`; true when p lies
    // on the surface; otherwise the nearest (u, v) found so far is kept
    // with its distance in bestResidual.
    bool parametersOf(const Vec3& p, double gradient, double& u, double& v,
                      double& bestResidual) const;
    bool containerInterval(const Ray& ray, double& t0, double& t1) const;
    // Partial derivatives of the point by central differences.
    void derivatives(double u, double v, Vec3& pu, Vec3& pv) const;

    ParametricSettings s_;
    std::vector<TreeNode> tree_;
    double scale_;  // the container's size, for tolerances
};

}  // namespace frameray::scene
