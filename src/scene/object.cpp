#include "scene/object.h"

#include <algorithm>
#include <cmath>
#include <typeinfo>

#include "scene/blob.h"
#include "scene/csg.h"
#include "scene/hit_tolerance.h"
#include "scene/quadric.h"
#include "scene/scratch.h"

namespace frameray::scene {

namespace {

using ScratchHits = ScratchVector<SurfaceHit>;

bool visibleTo(const Object& primitive, RayKind kind) {
    switch (kind) {
        case RayKind::Camera:
            return !primitive.noImage;
        case RayKind::Reflection:
            return !primitive.noReflection;
        case RayKind::Shadow:
            return !primitive.noShadow;
        case RayKind::Photon:
            return !primitive.noShadow && !primitive.noImage;
        case RayKind::Radiosity:
            return !primitive.noRadiosity;
        case RayKind::Any:
            return true;
    }
    return true;
}

std::shared_ptr<const Object> transformedCopy(const ObjectRef& obj, const Transform& t) {
    auto copy = std::make_shared<Object>(*obj);
    copy->transformBy(t);
    return copy;
}

template <typename List>
Bounds intersectAll(Bounds b, const List& objects, Bounds (Object::*bounds)() const) {
    for (const ObjectRef& o : objects) b = b.intersected(((*o).*bounds)());
    return b;
}

}  // namespace

void Object::transformBy(const Transform& t) {
    if (shape) {
        transform = transform.then(t);
        if (auto placed = shape->placedBy(transform)) shape = std::move(placed);
    }
    for (ObjectRef& child : children) child = transformedCopy(child, t);
    if (!clippedBy.empty()) {
        std::vector<ObjectRef> moved;
        moved.reserve(clippedBy.size());
        for (const ObjectRef& clip : clippedBy) moved.push_back(transformedCopy(clip, t));
        clippedBy = std::move(moved);
    }
    for (ObjectRef& bound : boundedBy) bound = transformedCopy(bound, t);
    if (interiorTexture) {
        auto moved = std::make_shared<Texture>(*interiorTexture);
        moved->transformBy(t);
        interiorTexture = std::move(moved);
    }
    if (texture) {
        auto moved = std::make_shared<Texture>(*texture);
        moved->transformBy(t);
        texture = moved;
    }
    if (interior && !interior->media.empty()) {
        // The media's densities move with the object.
        auto moved = std::make_shared<Interior>(*interior);
        for (auto& m : moved->media) {
            auto media = std::make_shared<Media>(*m);
            media->transformBy(t);
            m = std::move(media);
        }
        interior = std::move(moved);
    }
    for (auto& component : componentTextures) {
        if (!component) continue;
        auto moved = std::make_shared<Texture>(*component);
        moved->transformBy(t);
        component = moved;
    }
}

// --- ray queries ------------------------------------------------------------

namespace {

// bounded_by: a ray that misses a bounding object and does not start
// inside it cannot see the object (povray's test, which is why an
// undersized bound cuts parts of the object away).
bool passesBoundedBy(const Object& obj, const Ray& ray, double tMin) {
    for (const ObjectRef& bound : obj.boundedBy) {
        SurfaceHit ignored;
        if (!bound->firstHit(ray, tMin, kInfinity, RayKind::Any, ignored) &&
            !bound->inside(ray.origin))
            return false;
    }
    return true;
}

// clipped_by also bounds: povray tests a clipped object only for rays
// that meet its bounding box, which is the box of its clipping objects
// (their common part), not its own: measured, a finite cylinder clipped
// by a height field shows wherever rays cross the height field's box; an
// infinite quadric's box is its part of that box (Cylinder_Y shows only
// where rays cross the height field's box inside the cylinder's x and z
// range, objects/csg/hfclip.pov). A closed clip's inside lies in its box,
// so this cuts nothing more; an open one (a height field, whose inside
// reaches down without end) cuts the object at the box. An inverted
// clip's inside is outside its box: never a bound here.
bool meetsClipBoxes(const Object& obj, const Ray& ray, double tMin, double tMax) {
    Bounds box = obj.clippedBy.box();
    // Quadric is final: its type alone answers what a dynamic_cast would.
    if (obj.shape && !obj.inverse && typeid(*obj.shape) == typeid(Quadric))
        box = obj.insideBoundsWithin(box);
    double from = tMin, to = tMax;
    return box.padded().clip(ray, from, to);
}

bool insideAllClips(const Object& obj, const Vec3& p) {
    return std::all_of(obj.clippedBy.begin(), obj.clippedBy.end(),
                       [&](const ObjectRef& c) { return c->inside(p); });
}

// The ray parameter below which `shape` sees no crossing: its own povray
// depth tolerance, a distance along the world ray (scene/hit_tolerance.h).
double shapeTolerance(const Shape& shape, const Ray& ray) {
    const double tolerance = shape.depthTolerance();
    if (tolerance <= 0) return 0;
    return scaledTolerance(tolerance, coordinateMagnitude(ray.origin, ray.origin)) /
           length(ray.direction);
}

}  // namespace

void Object::allHits(const Ray& ray, double tMin, double tMax, RayKind kind,
                     std::vector<SurfaceHit>& hits, bool inverted) const {
    // povray cuts an object at an undersized bound for what the camera
    // sees but not for the shadow it casts.
    if (kind != RayKind::Shadow && kind != RayKind::Photon && !boundedBy.empty() &&
        !passesBoundedBy(*this, ray, tMin))
        return;
    if (!clippedBy.empty() && !meetsClipBoxes(*this, ray, tMin, tMax)) return;
    const size_t from = hits.size();
    if (shape) {
        thread_local std::vector<double> ts;  // the shape call below never recurses
        ts.clear();
        // Object space without renormalising keeps t the same in every space.
        const Ray local{transform.inversePoint(ray.origin),
                        transform.inverseDirection(ray.direction)};
        shape->allHits(local, std::max(tMin, shapeTolerance(*shape, ray)), tMax, ts);
        for (const double t : ts) hits.push_back({t, this});
    } else {
        csg::allHits(*this, ray, tMin, tMax, kind, hits, inverted != inverse);
    }
    if (clippedBy.empty()) return;
    size_t kept = from;
    for (size_t r = from; r < hits.size(); ++r)
        if (insideAllClips(*this, ray.at(hits[r].t))) hits[kept++] = hits[r];
    hits.resize(kept);
}

bool Object::firstHit(const Ray& ray, double tMin, double tMax, RayKind kind,
                      SurfaceHit& hit) const {
    const bool plain = clippedBy.empty() && boundedBy.empty();
    if (shape && plain) {
        if (!visibleTo(*this, kind)) return false;
        const Ray local{transform.inversePoint(ray.origin),
                        transform.inverseDirection(ray.direction)};
        double t;
        if (!shape->firstHit(local, std::max(tMin, shapeTolerance(*shape, ray)), tMax, t))
            return false;
        hit = {t, this};
        return true;
    }
    if (!shape && plain && op == CsgOp::Union && !inverse) {
        // The nearest child hit; no inside tests needed.
        bool found = false;
        for (const ObjectRef& child : children) {
            SurfaceHit h;
            if (child->firstHit(ray, tMin, tMax, kind, h)) {
                hit = h;
                tMax = h.t;
                found = true;
            }
        }
        return found;
    }
    if (!shape) {
        // A CSG node: its crossings nearest first, each decided only
        // when the nearer ones are out (allHits' list, searched lazily).
        if (kind != RayKind::Shadow && !boundedBy.empty() && !passesBoundedBy(*this, ray, tMin))
            return false;
        struct Filter {
            const Object* self;
            const Ray* ray;
            RayKind kind;
        } filter{this, &ray, kind};
        return csg::firstAccepted(
            *this, ray, tMin, tMax, kind, inverse,
            [](const SurfaceHit& h, const void* context) {
                const auto& f = *static_cast<const Filter*>(context);
                return insideAllClips(*f.self, f.ray->at(h.t)) && visibleTo(*h.primitive, f.kind);
            },
            &filter, hit);
    }
    ScratchHits scratch;
    std::vector<SurfaceHit>& hits = scratch.get();
    allHits(ray, tMin, tMax, kind, hits);
    for (const SurfaceHit& h : hits) {
        if (visibleTo(*h.primitive, kind)) {
            hit = h;
            return true;
        }
    }
    return false;
}

// --- inside -----------------------------------------------------------------

bool Object::isPatch() const {
    return shape && shape->isPatch();
}

bool Object::warnsAsPatch() const {
    return shape && shape->warnsAsPatch();
}

namespace {

// The inside test with the object inverted `inverted` times more than
// its own inverse flag says.
bool insideAs(const Object& obj, const Vec3& p, bool inverted) {
    if (obj.isPatch()) return false;
    const bool inverse = obj.inverse != inverted;
    const bool raw =
        obj.shape ? obj.shape->inside(obj.transform.inversePoint(p)) : csg::inside(obj, p);
    const bool in = raw != inverse;
    // Inverting does not invert the clips (povray: difference { box
    // sphere clipped_by { plane } } removes the box beyond the plane).
    return in && insideAllClips(obj, p);
}

}  // namespace

bool Object::inside(const Vec3& p) const {
    return insideAs(*this, p, false);
}

bool Object::insideInverted(const Vec3& p) const {
    return insideAs(*this, p, true);
}

Vec3 Object::normalAt(const Vec3& p) const {
    return shape->worldNormal(transform.inversePoint(p), transform);
}

void Object::visitTextures(const Vec3& p, const Texture& own,
                           const std::function<void(const Texture&, double)>& visit) const {
    const auto* blob = dynamic_cast<const Blob*>(shape.get());
    if (componentTextures.empty() || !blob) return visit(own, 1.0);
    const Vec3 q = transform.inversePoint(p);
    const auto& components = blob->components();
    const size_t n = std::min(components.size(), componentTextures.size());
    double total = 0;
    for (size_t i = 0; i < n; ++i) total += std::fabs(components[i].field(q));
    if (!(total > 0)) return visit(own, 1.0);
    // The untextured components' shares go to the object's texture at once.
    double ownWeight = 0;
    for (size_t i = 0; i < n; ++i) {
        const double w = std::fabs(components[i].field(q)) / total;
        if (w == 0) continue;
        if (componentTextures[i])
            visit(*componentTextures[i], w);
        else
            ownWeight += w;
    }
    if (ownWeight > 0) visit(own, ownWeight);
}

// --- bounds -----------------------------------------------------------------

Bounds Object::surfaceBounds() const {
    // bounded_by plays no part: shadow rays see the whole object.
    const Bounds raw = shape ? shape->bounds().transformed(transform) : csg::surfaceBounds(*this);
    return intersectAll(raw, clippedBy, &Object::insideBounds);
}

Bounds Object::insideBounds() const {
    if (isPatch()) return {};
    Bounds raw = Bounds::infinite();
    if (!inverse)
        raw = shape ? shape->insideBounds().transformed(transform) : csg::insideBounds(*this);
    return intersectAll(raw, clippedBy, &Object::insideBounds);
}

Bounds Object::insideBoundsWithin(const Bounds& box) const {
    if (!shape || inverse || isPatch()) return insideBounds().intersected(box);
    const Bounds local = shape->insideBoundsWithin(box.transformedAxiswise(transform.inverse()));
    return intersectAll(local.transformedAxiswise(transform).intersected(box), clippedBy,
                        &Object::insideBounds);
}

Bounds Object::insideInvertedBounds() const {
    if (isPatch()) return {};
    Bounds raw = Bounds::infinite();
    if (inverse)
        raw = shape ? shape->insideBounds().transformed(transform) : csg::insideBounds(*this);
    return intersectAll(raw, clippedBy, &Object::insideBounds);
}

}  // namespace frameray::scene
