// isosurface { function { f(x, y, z) } ... } (seed 000 §3.4.4): the surface
// f = threshold inside a container box or sphere, f < threshold being
// inside. Found along each ray by subdividing the ray's part in the
// container, skipping pieces where `max_gradient` (a Lipschitz bound on f)
// proves there is no root, until pieces are shorter than `accuracy`.
#pragma once

#include <memory>

#include "scene/shapes.h"
#include "util/function_vm.h"

namespace frameray::scene {

struct IsosurfaceSettings {
    // f(x, y, z); must not use what the function VM cannot evaluate.
    std::shared_ptr<const CompiledFunction> function;
    bool sphereContainer = false;
    Vec3 boxLo{-1, -1, -1}, boxHi{1, 1, 1};  // contained_by { box }
    Vec3 center;                             // contained_by { sphere }
    double radius = 1;
    double threshold = 0;
    double accuracy = 0.001;
    double maxGradient = 1.1;
    // Without `open` the container's surface closes the shape where the
    // function is inside.
    bool open = false;
    // How many crossings one ray reports (max_trace; all_intersections
    // is unlimited). Only the first matters for plain objects; CSG needs
    // them all.
    int maxTrace = 1;
};

class Isosurface final : public Shape {
  public:
    explicit Isosurface(IsosurfaceSettings settings) : s_(std::move(settings)) {}
    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    Vec3 normal(const Vec3& p) const override;
    bool inside(const Vec3& p) const override;
    Bounds bounds() const override;
    const char* name() const override { return "isosurface"; }

    // f(p) - threshold: negative inside.
    double value(const Vec3& p) const {
        const double args[3] = {p.x, p.y, p.z};
        return s_.function->eval(args) - s_.threshold;
    }

  private:
    bool containerInterval(const Ray& ray, double& t0, double& t1) const;
    // Whether a ray from p along `direction` leaves the function's inside
    // (the function grows along it).
    bool leaves(const Vec3& p, const Vec3& direction) const;
    bool insideContainer(const Vec3& p) const;
    // How far p lies from the container's surface (for telling apart hits
    // on the container from hits on the function's surface).
    double containerDistance(const Vec3& p) const;

    IsosurfaceSettings s_;
};

}  // namespace frameray::scene
