// The render-side view of a scene: an Embree top-level BVH with one user
// geometry per bounded top-level object (conservative float bounds around
// double-precision shapes), plus a list of unbounded objects (planes...)
// tested outside the BVH. Immutable once built, shared by all threads.
#pragma once

#include <embree3/rtcore.h>
#include <tbb/enumerable_thread_specific.h>

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "scene/scene.h"

namespace frameray::render {

class Photons;

// Intersection tests of one frame by the kind of top-level object tested
// (a shape's name; a CSG tree counts once, under its operation), sorted by
// kind. A test is one exact (double-precision) test of an object the BVH
// could not rule out, or of an unbounded object.
using ShapeTestCounts = std::vector<std::pair<std::string, std::uint64_t>>;

// The closest surface a ray meets: its distance parameter and the
// primitive hit (for a CSG object, the child whose surface it is; its
// transform gives the normal and its texture the colour).
// What passes through object `obj`'s surface at p: black when its texture is
// opaque there (render-side, shared by shadow rays and their cache).
RGB lightPassing(const scene::Object& obj, const Vec3& p);

// As in povray, a ray sees no surface this far from its origin or farther.
inline constexpr double kMaxRayDistance = 1e7;

struct Hit {
    double t = scene::kInfinity;
    const scene::Object* object = nullptr;
};

class World {
  public:
    explicit World(const scene::Scene& scene);
    ~World();
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    // Closest hit with t in (tMin, min(tMax, kMaxRayDistance)) among the
    // surfaces `kind` rays see (camera rays skip no_image, reflected rays
    // no_reflection). Any ray may be asked, NaN or huge ones included.
    bool intersect(const scene::Ray& ray, double tMin, double tMax, Hit& hit,
                   scene::RayKind kind = scene::RayKind::Camera) const;
    // Whether anything that casts shadows lies in (tMin, tMax).
    bool occluded(const scene::Ray& ray, double tMin, double tMax) const;

    // The part of a light's colour that passes along (tMin, tMax) of a
    // shadow ray, as povray 3.7 computes it: every shadow-casting surface
    // crossed multiplies it by filter * pigment + transmit (the pigment at
    // the crossing), so an opaque surface stops it. `selfHit` is the
    // margin past one crossing where the search for the next starts.
    // Returns black as soon as nothing passes. `light`, when given, is the
    // light the ray goes to: the object that last blocked it (per thread)
    // is tried first. `startInside`, when not empty, lists the interiors
    // the ray starts in as the ray it comes from saw them (a media sample's
    // shadow ray: the camera ray's containers); their media are then
    // tracked as povray 3.7 tracks a shadow ray's interiors (see
    // ShadowInteriors in world.cpp) rather than from the surfaces' normals.
    RGB shadowFilter(const scene::Ray& ray, double tMin, double tMax, double selfHit,
                     const scene::Light* light = nullptr,
                     std::span<const scene::Interior* const> startInside = {}) const;

    const scene::Scene& scene() const { return scene_; }

    // The scene's photon map (render/photons.h), shot when the World is
    // built; null unless the scene turns photons on.
    const Photons* photons() const { return photons_.get(); }

    // The tests made so far by every thread; call once rendering is over.
    ShapeTestCounts shapeTests() const;

    // The BVH's primitives (the bounded top-level objects) and their world
    // bounds, both indexed by Embree's primID.
    struct Primitives {
        std::vector<const scene::Object*> objects;
        std::vector<scene::Bounds> bounds;
        std::vector<std::uint16_t> kinds;  // index into kindNames_, for the statistics
    };

  private:
    // Stretches of a shadow ray inside objects that are not hollow, where
    // fog does not dim the light (at most kCapacity of them).
    struct SolidSpans {
        static constexpr size_t kCapacity = 8;
        std::array<std::pair<double, double>, kCapacity> spans{};
        size_t count = 0;
        void add(double from, double to) {
            if (count < kCapacity && to > from) spans[count++] = {from, to};
        }
    };
    // shadowFilter without the scene's media and fogs; `solid`, when given,
    // receives the stretches inside objects that are not hollow.
    RGB surfaceFilter(const scene::Ray& ray, double tMin, double tMax, double selfHit,
                      const scene::Light* light, SolidSpans* solid,
                      std::span<const scene::Interior* const> startInside) const;
    // Puts a top-level object (or, for a plain union, its children) into
    // the BVH or the unbounded list.
    void add(const scene::Object* obj);
    // Records the primitives under `obj` whose surface bounds their object
    // from the other side (a difference's subtracted operands, `inverse`),
    // `flipped` telling whether `obj` itself is turned so.
    void noteInverted(const scene::Object& obj, bool flipped);
    // The normal of a primitive's surface pointing out of the top-level
    // object it belongs to (its own normal turned for the primitives
    // noteInverted recorded): a shadow ray entering an interior has it
    // facing back.
    Vec3 outwardNormal(const scene::Object& primitive, const Vec3& p) const;

    const scene::Scene& scene_;
    RTCDevice device_ = nullptr;
    RTCScene bvh_ = nullptr;
    Primitives bounded_;
    std::vector<const scene::Object*> unbounded_;
    std::vector<std::uint16_t> unboundedKinds_;
    bool hasBounded_ = false;
    std::unordered_set<const scene::Object*> inverted_;  // see noteInverted
    std::unique_ptr<const Photons> photons_;
    // A top-level object that blocked a shadow ray, with its statistics kind.
    // `bounds`: its box in the BVH (null for an unbounded object).
    struct Blocker {
        const scene::Object* object = nullptr;
        std::uint16_t kind = 0;
        const scene::Bounds* bounds = nullptr;
    };
    struct Occlusion {
        Blocker blocker;           // set when an opaque crossing was found
        bool translucent = false;  // a crossing that lets light through was seen
    };
    // An object the caller already tested with the same shadow ray (the
    // cached blocker) and what it found: it is not tested again.
    struct Tested {
        const scene::Object* object = nullptr;
        bool translucent = false;  // it was crossed where light passes
    };
    // Per-frame, per-thread state: the test counters (one per kind, so the
    // hot path takes no lock and shares no cache line) and the last blocker
    // of each light. The World lives for one frame, so no state outlives it.
    struct ThreadState {
        std::vector<std::uint64_t> tests;
        std::vector<Blocker> lastBlocker;  // indexed like scene().lights
    };
    // One any-hit search of (tMin, tMax) for a crossing that stops the light.
    Occlusion findOccluder(const scene::Ray& ray, double tMin, double tMax, ThreadState& state,
                           const scene::Light* photonLight, Tested tested) const;

    std::vector<std::string> kindNames_;
    mutable tbb::enumerable_thread_specific<ThreadState, tbb::cache_aligned_allocator<ThreadState>,
                                            tbb::ets_key_per_instance>
        tests_;
    std::uint16_t kindOf(const scene::Object& object);
    std::uint64_t* counters() const { return tests_.local().tests.data(); }
};

}  // namespace frameray::render
