// parametric { function { x(u, v) } function { y(u, v) } function { z(u, v) }
// <u1, v1>, <u2, v2> ... } (povray 3.7): the surface swept by the point
// (x, y, z)(u, v) over a rectangle of (u, v), clipped to a container box or
// sphere.
//
// A ray is met as povray 3.7 meets it (the rule read from its source and
// checked against its trace() and images; the code is ours): the (u, v)
// rectangle is halved along its longer side, depth first, lower half
// first. Each coordinate is bounded over a piece from its values at the
// piece's four corners, assuming it changes at the rate max_gradient (and,
// as povray does, shifted down by `accuracy`); a piece whose three slabs
// the ray does not cross together within the container is dropped. A
// piece is small enough when its longer side, or the longest stretch of
// the ray through one of its slabs, is below `accuracy`: the ray then
// meets the surface where it enters the piece's z slab (the last slab it
// is not parallel to), nearer than any found before and past the
// container's entry plus 4 accuracy. Only that first crossing is
// reported, so CSG and clipped_by see no surface behind it, and the
// surface encloses nothing (its inside test is false even when inverted).
// The normal and uv_mapping's (u, v) come from the piece's lower corner,
// the normal by differences one `accuracy` apart. `precompute D, x, y, z`
// tabulates the bounds of the first D levels of pieces, as povray does;
// they are not the same bounds as the ones computed on the way, so it
// changes the image a little, as in povray.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

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
    // precompute D, x, y, z: D levels (0: none) for the coordinates named.
    int precomputeDepth = 0;
    bool precomputeAxis[3] = {false, false, false};
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
    // uv_mapping: the (u, v) the hit at p was found with.
    bool uv(const Vec3& p, double& u, double& v) const override;

  private:
    // Lower and upper bounds of one coordinate over a piece of (u, v).
    struct Range {
        double lo, hi;
    };
    // The bounds of coordinate `axis` over [u0, u1] x [v0, v1] from its
    // corner values, as povray bounds them.
    Range coordinateRange(int axis, double u0, double u1, double v0, double v1) const;
    // Fills precomputed_ for the first `depth` levels of pieces (numbered
    // from 1, the children of piece n are 2n and 2n + 1).
    void precompute(int axis, std::uint64_t number, double u0, double u1, double v0, double v1);
    // The ray's span through the container (povray's rule for a ray
    // starting inside); false when it misses it.
    bool containerSpan(const Ray& ray, double& t0, double& t1) const;
    // (u, v) of the hit at p found by this shape on this thread, if any.
    bool rememberedUv(const Vec3& p, double& u, double& v) const;
    // The normal from the differences one `accuracy` apart at (u, v).
    Vec3 normalAtParameters(double u, double v) const;

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
    // Partial derivatives of the point by central differences.
    void derivatives(double u, double v, Vec3& pu, Vec3& pv) const;

    ParametricSettings s_;
    std::array<std::vector<Range>, 3> precomputed_;  // by piece number; empty: not tabulated
    std::vector<TreeNode> tree_;
    double scale_;  // the container's size, for tolerances
};

}  // namespace frameray::scene
