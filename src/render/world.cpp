#include "render/world.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <limits>
#include <span>
#include <stdexcept>

#include "render/atmosphere.h"
#include "render/media.h"
#include "render/optics.h"
#include "render/photons.h"

namespace frameray::render {

namespace {

// Carries the double-precision ray through Embree's float traversal: the
// callbacks intersect in double and record the result here; Embree's own
// float tfar is only used (rounded outward) to cull farther subtrees.
struct TraceContext {
    RTCIntersectContext embree;  // must be first: Embree passes a pointer to it
    const scene::Ray* ray;
    double tMin;
    double tMax;
    const scene::Object* hitObject;
    // Shadow queries: the top-level object that blocks the light, and
    // whether a surface was crossed that lets some light through.
    const scene::Object* blocker = nullptr;
    std::uint16_t blockerKind = 0;
    const scene::Bounds* blockerBounds = nullptr;
    bool translucent = false;
    // The object the caller already tested with this ray (World::Tested).
    const scene::Object* tested = nullptr;
    bool testedTranslucent = false;
    // With photons on, the light whose shadow rays these are: photon
    // targets that refract its photons stop it (Photons::photonShadow).
    const scene::Light* photonLight = nullptr;
    scene::RayKind kind = scene::RayKind::Camera;  // which flags hide surfaces from intersect()
    std::uint64_t* tests = nullptr;                // the calling thread's counters, by kind
    // An exception must not unwind through Embree (it would be lost there
    // and the object silently missing): the callbacks keep it here and the
    // caller rethrows it once Embree has returned.
    std::exception_ptr error;
};

// Runs a callback's body; an exception is kept for the caller, and the
// search ends (a ray with an error has no meaningful hit).
template <typename Body>
void guarded(TraceContext* ctx, Body body) {
    if (ctx->error) return;
    try {
        body();
    } catch (...) {
        ctx->error = std::current_exception();
    }
}

// The hollow objects with media a shadow ray is in as it crosses their
// surfaces (World::surfaceFilter): the light is dimmed by the media between
// where the ray enters and leaves, or from its start when it starts inside
// (a media sample point), or to its end when the light is inside (measured:
// povray's shadow under a box of absorbing media).
//
// A media sample's shadow ray (`startInside` given) instead starts in the
// containers its camera ray was in, and each surface of a container it
// crosses toggles it: out if the ray was in, in otherwise, whatever way the
// surface faces. This is povray 3.7's bookkeeping (fact read in its source,
// render/trace.cpp: the shadow ray copies the camera ray's interior list and
// adds or removes the interior at every crossing). It differs from the
// surfaces' normals for a sample lying on the surface the camera ray entered
// by (method 3's first point of an interval) when the way to the light goes
// back through the container's own hollow: povray dims that light over the
// hollow only, then counts the ray outside for the rest (measured:
// benchmark.pov's cloud shell lights a wedge of cloud toward the light;
// conformance media_shell_sample_edge). A container entered that way, by a
// surface facing away, does not dim the light beyond the last crossing.
class MediaCrossings {
  public:
    MediaCrossings(const scene::Ray& ray, double tMin,
                   std::span<const scene::Interior* const> startInside)
        : ray_(ray), tMin_(tMin), speed_(length(ray.direction)), toggles_(!startInside.empty()) {
        for (const scene::Interior* in : startInside)
            if (in && !in->media.empty() && count_ < kCapacity)
                inside_[count_++] = {in, tMin, false};
    }
    // The ray crosses the surface of a hollow object with media `in` at t;
    // `entering`: the surface faces against the ray.
    void cross(const scene::Interior& in, bool entering, double t, RGB& passed) {
        for (size_t i = 0; i < count_; ++i) {
            if (inside_[i].interior != &in) continue;
            passed *= between(in, inside_[i].from, t);
            inside_[i] = inside_[--count_];
            return;
        }
        if (entering || toggles_) {
            if (count_ < kCapacity) inside_[count_++] = {&in, t, entering};
        } else {
            passed *= between(in, tMin_, t);
        }
    }
    // The ray reaches the light at tMax.
    void finish(double tMax, RGB& passed) const {
        for (size_t i = 0; i < count_; ++i)
            if (inside_[i].entered) passed *= between(*inside_[i].interior, inside_[i].from, tMax);
    }

  private:
    RGB between(const scene::Interior& in, double t0, double t1) const {
        MediaSet set;
        set.add(in.media);
        const scene::Ray unit{ray_.at(t0), ray_.direction * (1.0 / speed_)};
        return mediaTransmittance(unit, (t1 - t0) * speed_, set);
    }
    struct Inside {
        const scene::Interior* interior;
        double from;
        bool entered;  // through a surface facing against the ray
    };
    static constexpr size_t kCapacity = 8;
    const scene::Ray& ray_;
    double tMin_, speed_;
    bool toggles_;
    std::array<Inside, kCapacity> inside_{};
    size_t count_ = 0;
};

}  // namespace

namespace {

// lightPassing, except that with photons a target refracting the light's
// photons lets nothing through to it (`photonLight`: that light, or null).
RGB passing(const scene::Object& obj, const Vec3& p, const scene::Light* photonLight) {
    if (photonLight && Photons::photonShadow(*photonLight, obj)) return RGB(0.0);
    return lightPassing(obj, p);
}

}  // namespace

RGB lightPassing(const scene::Object& obj, const Vec3& p) {
    if (obj.componentTextures.empty()) {
        if (!obj.texture) return RGB(0.0);  // the default texture is opaque black
        // uv_mapping's point, found only when the texture asks for it.
        const Vec3 uv = obj.texture->usesUv() ? obj.surfaceUv(p) : p;
        return obj.texture->throughAt(p, &uv);
    }
    // A blob's component textures, blended as for shading (an untextured
    // part with the default texture is opaque).
    RGB through(0.0);
    const scene::Texture opaque;
    const Vec3 uv = obj.surfaceUv(p);
    obj.visitTextures(p, obj.texture ? *obj.texture : opaque,
                      [&](const scene::Texture& t, double w) {
                          if (&t != &opaque) through += t.throughAt(p, &uv) * w;
                      });
    return through;
}

namespace {

float roundUp(double v) {
    float f = static_cast<float>(v);
    return static_cast<double>(f) < v ? std::nextafter(f, std::numeric_limits<float>::infinity())
                                      : f;
}
float roundDown(double v) {
    float f = static_cast<float>(v);
    return static_cast<double>(f) > v ? std::nextafter(f, -std::numeric_limits<float>::infinity())
                                      : f;
}

// All bounded objects are the primitives of one user geometry (one Embree
// geometry per object costs about a kilobyte and a commit each, which on a
// 100 000-object scene is more than the whole render); the user pointer is
// the World's primitive table and primID indexes it.
const World::Primitives& primitivesOf(void* userPtr) {
    return *static_cast<const World::Primitives*>(userPtr);
}
const scene::Object& objectOf(void* userPtr, unsigned primID) {
    return *primitivesOf(userPtr).objects[primID];
}

void boundsCallback(const RTCBoundsFunctionArguments* args) {
    // Computed once by World's constructor (a CSG object's bounds walk its
    // whole tree).
    const scene::Bounds& b = primitivesOf(args->geometryUserPtr).bounds[args->primID];
    // Pad by a relative margin so float traversal can never miss a surface
    // the double-precision test would find.
    const Vec3 pad = (b.hi - b.lo) * 1e-6 + Vec3(1e-30);
    auto widen = [](double v, double p) { return std::fabs(v) * 1e-6 + p; };
    RTCBounds* o = args->bounds_o;
    o->lower_x = roundDown(b.lo.x - widen(b.lo.x, pad.x));
    o->lower_y = roundDown(b.lo.y - widen(b.lo.y, pad.y));
    o->lower_z = roundDown(b.lo.z - widen(b.lo.z, pad.z));
    o->upper_x = roundUp(b.hi.x + widen(b.hi.x, pad.x));
    o->upper_y = roundUp(b.hi.y + widen(b.hi.y, pad.y));
    o->upper_z = roundUp(b.hi.z + widen(b.hi.z, pad.z));
}

void intersectCallback(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* ctx = reinterpret_cast<TraceContext*>(args->context);
    guarded(ctx, [&] {
        ++ctx->tests[primitivesOf(args->geometryUserPtr).kinds[args->primID]];
        const scene::Object* obj = &objectOf(args->geometryUserPtr, args->primID);
        scene::SurfaceHit h;
        if (!obj->firstHit(*ctx->ray, ctx->tMin, ctx->tMax, ctx->kind, h)) return;
        ctx->tMax = h.t;
        ctx->hitObject = h.primitive;
        RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
        RTCRayN_tfar(ray, args->N, 0) = roundUp(h.t);
        RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
        RTCHitN_geomID(hit, args->N, 0) = args->geomID;
        RTCHitN_primID(hit, args->N, 0) = args->primID;
    });
}

void occludedCallback(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* ctx = reinterpret_cast<TraceContext*>(args->context);
    guarded(ctx, [&] {
        const std::uint16_t kind = primitivesOf(args->geometryUserPtr).kinds[args->primID];
        const scene::Object* obj = &objectOf(args->geometryUserPtr, args->primID);
        if (obj == ctx->tested) {
            ctx->translucent = ctx->translucent || ctx->testedTranslucent;
            return;
        }
        ++ctx->tests[kind];
        scene::SurfaceHit h;
        if (!obj->firstHit(*ctx->ray, ctx->tMin, ctx->tMax, scene::RayKind::Shadow, h)) return;
        if (!passing(*h.primitive, ctx->ray->at(h.t), ctx->photonLight).isBlack()) {
            // Light may pass here: keep searching for an opaque crossing.
            ctx->translucent = true;
            return;
        }
        ctx->blocker = obj;
        ctx->blockerKind = kind;
        ctx->blockerBounds = &primitivesOf(args->geometryUserPtr).bounds[args->primID];
        // Embree's convention for "occluded".
        RTCRayN_tfar(args->ray, args->N, 0) = -std::numeric_limits<float>::infinity();
    });
}

// Embree traces float rays and asserts (aborting the process) unless their
// origin and direction are finite and below about 1.8e18 in magnitude and
// tfar is not NaN. A scene can make any of them (a light at
// <pow(-8,1/3),1,1>, a camera at 1e20): such a ray skips Embree and meets
// no bounded object. It could meet one only beyond kMaxRayDistance from a
// finite origin, or at 1e17 from the origin of the scene, where float
// bounds no longer separate anything.
// Whether the ray's stretch (tMin, tMax) may meet the box: a slab test
// on the box widened a little (a box from Bounds is conservative; the
// margin keeps rounding in this test from ever culling a real hit).
bool rayMayMeet(const scene::Ray& ray, double tMin, double tMax, const scene::Bounds& box) {
    double tNear = tMin, tFar = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        const double lo = box.lo[axis], hi = box.hi[axis];
        const double pad = 1e-6 * std::max({1.0, std::fabs(lo), std::fabs(hi)});
        const double o = ray.origin[axis], d = ray.direction[axis];
        if (d == 0) {
            if (o < lo - pad || o > hi + pad) return false;
            continue;
        }
        double t0 = (lo - pad - o) / d, t1 = (hi + pad - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        // NaN (an infinite box side) leaves the interval as it is.
        if (t0 > tNear) tNear = t0;
        if (t1 < tFar) tFar = t1;
        if (tNear > tFar) return false;
    }
    return true;
}

bool embreeCanTrace(const scene::Ray& ray, double tMax) {
    constexpr double kLimit = 1e17;
    const auto small = [](const Vec3& v) {
        return std::fabs(v.x) <= kLimit && std::fabs(v.y) <= kLimit && std::fabs(v.z) <= kLimit;
    };
    return small(ray.origin) && small(ray.direction) && !std::isnan(tMax);
}

RTCRay toEmbreeRay(const scene::Ray& ray, double tMax) {
    RTCRay r{};
    r.org_x = static_cast<float>(ray.origin.x);
    r.org_y = static_cast<float>(ray.origin.y);
    r.org_z = static_cast<float>(ray.origin.z);
    r.dir_x = static_cast<float>(ray.direction.x);
    r.dir_y = static_cast<float>(ray.direction.y);
    r.dir_z = static_cast<float>(ray.direction.z);
    // tnear 0: the double-precision tMin is applied inside the callbacks.
    r.tnear = 0.0f;
    r.tfar = std::isinf(tMax) ? std::numeric_limits<float>::infinity() : roundUp(tMax);
    r.mask = 0xFFFFFFFFu;
    r.flags = 0;
    return r;
}

const char* csgName(scene::CsgOp op) {
    switch (op) {
        case scene::CsgOp::Union:
            return "union";
        case scene::CsgOp::Merge:
            return "merge";
        case scene::CsgOp::Intersection:
            return "intersection";
        case scene::CsgOp::Difference:
            return "difference";
    }
    return "csg";
}

}  // namespace

std::uint16_t World::kindOf(const scene::Object& object) {
    const std::string name = object.isCsg() ? csgName(object.op) : object.shape->name();
    const auto it = std::find(kindNames_.begin(), kindNames_.end(), name);
    if (it != kindNames_.end()) return static_cast<std::uint16_t>(it - kindNames_.begin());
    kindNames_.push_back(name);
    return static_cast<std::uint16_t>(kindNames_.size() - 1);
}

ShapeTestCounts World::shapeTests() const {
    std::vector<std::uint64_t> sum(kindNames_.size(), 0);
    for (const ThreadState& state : tests_)
        for (size_t i = 0; i < state.tests.size(); ++i) sum[i] += state.tests[i];
    ShapeTestCounts out;
    for (size_t i = 0; i < kindNames_.size(); ++i) out.emplace_back(kindNames_[i], sum[i]);
    std::sort(out.begin(), out.end());
    return out;
}

World::World(const scene::Scene& scene)
    : scene_(scene), tests_([this] {
          ThreadState state;
          state.tests.assign(kindNames_.size(), 0);
          state.lastBlocker.assign(scene_.lights.size(), Blocker{});
          return state;
      }) {
    device_ = rtcNewDevice("verbose=0");
    if (!device_) throw std::runtime_error("Embree: cannot create a device");
    bvh_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(bvh_, RTC_BUILD_QUALITY_HIGH);
    for (const auto& obj : scene.objects) {
        add(obj.get());
        noteInverted(*obj, false);
    }
    if (!bounded_.objects.empty()) {
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(g, static_cast<unsigned>(bounded_.objects.size()));
        rtcSetGeometryUserData(g, &bounded_);  // never changes after this
        rtcSetGeometryBoundsFunction(g, boundsCallback, nullptr);
        rtcSetGeometryIntersectFunction(g, intersectCallback);
        rtcSetGeometryOccludedFunction(g, occludedCallback);
        rtcCommitGeometry(g);
        rtcAttachGeometry(bvh_, g);
        rtcReleaseGeometry(g);
        hasBounded_ = true;
    }
    rtcCommitScene(bvh_);
    // Photons are traced through the finished BVH.
    photons_ = Photons::build(*this);
}

void World::add(const scene::Object* obj) {
    if (obj->noImage && obj->noShadow && obj->noReflection && obj->noRadiosity)
        return;  // invisible to every ray kind
    // A plain union's first hit is its nearest child's: its children join
    // the BVH one by one (povray splits unions the same way), instead of
    // a union of thousands being searched child by child.
    if (obj->isCsg() && obj->op == scene::CsgOp::Union && !obj->inverse && obj->clippedBy.empty() &&
        obj->boundedBy.empty()) {
        for (const scene::ObjectRef& child : obj->children) add(child.get());
        return;
    }
    const scene::Bounds bounds = obj->surfaceBounds();
    if (bounds.isEmpty()) return;  // nothing to hit (say, a CSG intersection of disjoint parts)
    if (!bounds.isFinite()) {
        unbounded_.push_back(obj);
        unboundedKinds_.push_back(kindOf(*obj));
        return;
    }
    bounded_.objects.push_back(obj);
    bounded_.bounds.push_back(bounds);
    bounded_.kinds.push_back(kindOf(*obj));
}

void World::noteInverted(const scene::Object& obj, bool flipped) {
    flipped = flipped != obj.inverse;
    if (!obj.isCsg()) {
        if (flipped) inverted_.insert(&obj);
        return;
    }
    for (size_t i = 0; i < obj.children.size(); ++i)
        noteInverted(*obj.children[i], flipped != (obj.op == scene::CsgOp::Difference && i > 0));
}

Vec3 World::outwardNormal(const scene::Object& primitive, const Vec3& p) const {
    const Vec3 n = primitive.normalAt(p);
    return inverted_.count(&primitive) ? -n : n;
}

World::~World() {
    if (bvh_) rtcReleaseScene(bvh_);
    if (device_) rtcReleaseDevice(device_);
}

bool World::intersect(const scene::Ray& ray, double tMin, double tMax, Hit& hit,
                      scene::RayKind kind) const {
    TraceContext ctx;
    rtcInitIntersectContext(&ctx.embree);
    ctx.ray = &ray;
    ctx.tMin = tMin;
    // povray sees nothing from kMaxRayDistance on (measured: a plane 0.99e7
    // in front of the camera shows, one 1e7 away does not).
    ctx.tMax = std::min(tMax, kMaxRayDistance / length(ray.direction));
    ctx.hitObject = nullptr;
    ctx.kind = kind;
    ctx.tests = counters();
    // Unbounded objects first, in scene order: a bounded surface at the
    // same distance as one of them must be strictly nearer to win, as in
    // povray with bounding on (measured: a plane wins over a box face
    // lying in it whichever is declared first; issue 22, filtfun).
    for (size_t i = 0; i < unbounded_.size(); ++i) {
        const scene::Object* obj = unbounded_[i];
        ++ctx.tests[unboundedKinds_[i]];
        scene::SurfaceHit h;
        if (obj->firstHit(ray, tMin, ctx.tMax, kind, h)) {
            ctx.tMax = h.t;
            ctx.hitObject = h.primitive;
        }
    }
    if (hasBounded_ && embreeCanTrace(ray, ctx.tMax)) {
        RTCRayHit rh{};
        rh.ray = toEmbreeRay(ray, ctx.tMax);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(bvh_, &ctx.embree, &rh);
        if (ctx.error) std::rethrow_exception(ctx.error);
    }
    if (!ctx.hitObject) return false;
    hit.t = ctx.tMax;
    hit.object = ctx.hitObject;
    return true;
}

World::Occlusion World::findOccluder(const scene::Ray& ray, double tMin, double tMax,
                                     ThreadState& state, const scene::Light* photonLight,
                                     Tested tested) const {
    Occlusion found;
    std::uint64_t* tests = state.tests.data();
    for (size_t i = 0; i < unbounded_.size(); ++i) {
        const scene::Object* obj = unbounded_[i];
        if (obj == tested.object) {
            found.translucent = found.translucent || tested.translucent;
            continue;
        }
        ++tests[unboundedKinds_[i]];
        scene::SurfaceHit h;
        if (!obj->firstHit(ray, tMin, tMax, scene::RayKind::Shadow, h)) continue;
        if (passing(*h.primitive, ray.at(h.t), photonLight).isBlack()) {
            found.blocker = {obj, unboundedKinds_[i]};
            return found;
        }
        found.translucent = true;
    }
    if (!hasBounded_ || !embreeCanTrace(ray, tMax)) return found;
    TraceContext ctx;
    rtcInitIntersectContext(&ctx.embree);
    ctx.ray = &ray;
    ctx.tMin = tMin;
    ctx.tMax = tMax;
    ctx.hitObject = nullptr;
    ctx.kind = scene::RayKind::Shadow;
    ctx.tests = tests;
    ctx.photonLight = photonLight;
    ctx.tested = tested.object;
    ctx.testedTranslucent = tested.translucent;
    RTCRay r = toEmbreeRay(ray, tMax);
    rtcOccluded1(bvh_, &ctx.embree, &r);
    if (ctx.error) std::rethrow_exception(ctx.error);
    if (ctx.blocker) found.blocker = {ctx.blocker, ctx.blockerKind, ctx.blockerBounds};
    found.translucent = found.translucent || ctx.translucent;
    return found;
}

bool World::occluded(const scene::Ray& ray, double tMin, double tMax) const {
    const Occlusion o = findOccluder(ray, tMin, tMax, tests_.local(), nullptr, Tested{});
    return o.blocker.object || o.translucent;
}

RGB World::shadowFilter(const scene::Ray& ray, double tMin, double tMax, double selfHit,
                        const scene::Light* light,
                        std::span<const scene::Interior* const> startInside) const {
    const bool fogs = light && light->mediaAttenuation && light->mediaInteraction &&
                      !scene_.atmosphere.fogs.empty() && std::isfinite(tMax);
    SolidSpans solid;
    RGB passed =
        surfaceFilter(ray, tMin, tMax, selfHit, light, fogs ? &solid : nullptr, startInside);
    if (fogs && !passed.isBlack()) {
        // No fog inside objects that are not hollow (measured: the shadow
        // of interior/media/hollow1.pov's solid glass sphere under fog
        // and a media_attenuation light is lighter than the hollow one's).
        const double speed = length(ray.direction);
        const Vec3 unit = ray.direction * (1.0 / speed);
        std::array<std::pair<Vec3, double>, SolidSpans::kCapacity> spans{};
        for (size_t i = 0; i < solid.count; ++i)
            spans[i] = {ray.at(solid.spans[i].first),
                        (solid.spans[i].second - solid.spans[i].first) * speed};
        passed *= fogLightTransmittance(scene_, ray.at(tMin), unit, (tMax - tMin) * speed,
                                        std::span(spans.data(), solid.count));
    }
    // media_attenuation: the scene's media dim the light on its way (povray
    // leaves it out by default, and for a light without media_interaction;
    // measured).
    if (light && light->mediaAttenuation && light->mediaInteraction &&
        !scene_.atmosphere.media.empty() && !passed.isBlack() && std::isfinite(tMax)) {
        MediaSet set;
        set.add(scene_.atmosphere.media);
        const double speed = length(ray.direction);
        const scene::Ray unit{ray.at(tMin), ray.direction * (1.0 / speed)};
        passed *= mediaTransmittance(unit, (tMax - tMin) * speed, set);
    }
    return passed;
}

RGB World::surfaceFilter(const scene::Ray& ray, double tMin, double tMax, double selfHit,
                         const scene::Light* light, SolidSpans* solid,
                         std::span<const scene::Interior* const> startInside) const {
    ThreadState& state = tests_.local();
    // povray stops such shadow rays only once surface photons exist.
    const scene::Light* photonLight = photons_ && !photons_->surfaceMap().empty() ? light : nullptr;
    // povray's shadow cache: the object that last blocked this light is
    // tried first, since neighbouring points are usually shadowed by the
    // same object. A hit that lets no light through settles the ray.
    Blocker* cached = nullptr;
    if (light && !scene_.lights.empty() && light >= scene_.lights.data() &&
        light < scene_.lights.data() + scene_.lights.size())
        cached = &state.lastBlocker[static_cast<size_t>(light - scene_.lights.data())];
    // Its box is tried first (a ray that misses it cannot hit it); the
    // search below does not test it again.
    Tested tested;
    if (cached && cached->object) {
        tested.object = cached->object;
        if (!cached->bounds || rayMayMeet(ray, tMin, tMax, *cached->bounds)) {
            ++state.tests[cached->kind];
            scene::SurfaceHit h;
            if (cached->object->firstHit(ray, tMin, tMax, scene::RayKind::Shadow, h)) {
                if (passing(*h.primitive, ray.at(h.t), photonLight).isBlack()) return RGB(0.0);
                tested.translucent = true;
            }
        }
    }
    // Most shadow rays are either clear or blocked by something opaque:
    // one any-hit search settles both.
    const Occlusion o = findOccluder(ray, tMin, tMax, state, photonLight, tested);
    if (o.blocker.object) {
        if (cached) *cached = o.blocker;
        return RGB(0.0);
    }
    if (!o.translucent) return RGB(1.0);
    // Only translucent surfaces in the way: multiply what each lets through.
    RGB passed(1.0);
    double from = tMin;
    Hit hit;
    // Fading interiors the ray has entered, with where: the light is faded
    // over the distance from entry to exit (measured: povray's shadow
    // under a fade_distance sphere is as dark as the fade of the chord
    // predicts). Leaving one it did not enter (a ray starting inside, as
    // from a stone under fading water) fades the light over the distance
    // from the ray's start: this is how povray 3.7 fades the light that
    // reaches a surface inside a fading interior (measured: a lit floor
    // under benchmark.pov's water darkens with depth only when the water
    // casts shadows; with no_shadow it keeps its whole light). At
    // the default fade_power 0 shadow rays do not fade, though camera rays
    // pass half the light (measured: interior/atten1.pov's shadows).
    struct Inside {
        const scene::Interior* interior;
        double from;
    };
    std::array<Inside, 8> inside{};
    size_t insideCount = 0;
    const double speed = length(ray.direction);
    auto crossFading = [&](const scene::Object& obj, const Vec3& p, double t) {
        const scene::Interior* in = obj.interior.get();
        if (!in || !in->fades() || in->fadePower == 0) return;
        for (size_t i = 0; i < insideCount; ++i) {
            if (inside[i].interior != in) continue;
            passed *= interiorFade(*in, (t - inside[i].from) * speed);
            inside[i] = inside[--insideCount];
            return;
        }
        if (dot(outwardNormal(obj, p), ray.direction) < 0) {
            if (insideCount < inside.size()) inside[insideCount++] = {in, t};
        } else {
            passed *= interiorFade(*in, (t - tMin) * speed);
        }
    };
    MediaCrossings media(ray, tMin, startInside);
    // Objects that are not hollow: where the ray is inside them (from its
    // start when it leaves one it did not enter).
    struct InSolid {
        const void* key;
        double from;
    };
    std::array<InSolid, SolidSpans::kCapacity> inSolid{};
    size_t inSolidCount = 0;
    auto crossSolid = [&](const scene::Object& obj, const Vec3& p, double t) {
        if (!solid || obj.hollow) return;
        const void* key = obj.interior ? static_cast<const void*>(obj.interior.get()) : &obj;
        for (size_t i = 0; i < inSolidCount; ++i) {
            if (inSolid[i].key != key) continue;
            solid->add(inSolid[i].from, t);
            inSolid[i] = inSolid[--inSolidCount];
            return;
        }
        if (dot(outwardNormal(obj, p), ray.direction) < 0) {
            if (inSolidCount < inSolid.size()) inSolid[inSolidCount++] = {key, t};
        } else {
            solid->add(tMin, t);
        }
    };
    while (intersect(ray, from, tMax, hit, scene::RayKind::Shadow)) {
        const Vec3 p = ray.at(hit.t);
        crossFading(*hit.object, p, hit.t);
        if (const scene::Interior* in = hit.object->interior.get();
            in && !in->media.empty() && hit.object->hollow)
            media.cross(*in, dot(outwardNormal(*hit.object, p), ray.direction) < 0, hit.t, passed);
        crossSolid(*hit.object, p, hit.t);
        const RGB through = passing(*hit.object, p, photonLight);
        if (through.isBlack()) return RGB(0.0);
        passed *= through * fakeCaustics(*hit.object, p, ray.direction);
        if (passed.isBlack()) return passed;
        const double scale = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
        from = hit.t + std::max(selfHit, scale * 1e-9);
    }
    if (std::isfinite(tMax)) {
        media.finish(tMax, passed);
        for (size_t i = 0; i < inSolidCount; ++i) solid->add(inSolid[i].from, tMax);
    }
    return passed;
}

}  // namespace frameray::render
