#include "scene/csg.h"

#include <algorithm>
#include <cstdint>

#include "scene/scratch.h"

namespace frameray::scene::csg {

namespace {

// Whether child `self`'s crossing at p lies on the node's boundary. An
// inverted union keeps only its outer crossings, as a merge (measured:
// povray hides the overlap of a subtracted union's operands, and of an
// `inverse` union's).
bool keepsCrossing(const Object& node, size_t self, const Vec3& p, bool inverted) {
    const auto& kids = node.children;
    for (size_t j = 0; j < kids.size(); ++j) {
        if (j == self) continue;
        const Object& other = *kids[j];
        switch (node.op) {
            case CsgOp::Union:
                if (!inverted) return true;
                if (other.inside(p)) return false;
                break;
            case CsgOp::Merge:
                if (other.inside(p)) return false;
                break;
            case CsgOp::Intersection:
                if (!other.inside(p)) return false;
                break;
            case CsgOp::Difference:
                if (j == 0 ? !other.inside(p) : !other.insideInverted(p)) return false;
                break;
        }
    }
    return true;
}

// The region a child stands for as an operand of the node: a subtracted
// child of a difference counts inverted.
Bounds operandInsideBounds(const Object& node, size_t i) {
    const Object& child = *node.children[i];
    return node.op == CsgOp::Difference && i > 0 ? child.insideInvertedBounds()
                                                 : child.insideBounds();
}

// Whether the ray (from tMin on) passes through an axis-aligned box.
bool rayMeetsBox(const Ray& ray, double tMin, const Bounds& b) {
    double tNear = tMin, tFar = kInfinity;
    for (int axis = 0; axis < 3; ++axis) {
        const double o = ray.origin[axis], d = ray.direction[axis];
        if (d == 0) {
            if (o < b.lo[axis] || o > b.hi[axis]) return false;
            continue;
        }
        double t0 = (b.lo[axis] - o) / d, t1 = (b.hi[axis] - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        tNear = std::max(tNear, t0);
        tFar = std::min(tFar, t1);
        if (tNear > tFar) return false;
    }
    return true;
}

// povray skips an intersection (or difference) along rays that miss its
// bounding box, the common part of its uninverted operands' boxes. That is
// invisible unless an operand's inside reaches past its box (a disc, whose
// box is a thin slab): then the slab limits which rays see the rest.
// Elsewhere the box only saves work, so it is only computed for those.
bool rayMeetsOperandBoxes(const Object& node, const Ray& ray, double tMin) {
    // Called for every ray that reaches the node: decide whether the box
    // matters before computing it (operand bounds cost a walk of the tree).
    auto uninverted = [&](size_t i) {
        return node.children[i]->inverse == (node.op == CsgOp::Difference && i > 0);
    };
    bool matters = false;
    for (size_t i = 0; i < node.children.size() && !matters; ++i) {
        const Object& child = *node.children[i];
        matters = uninverted(i) && child.shape && child.shape->insideReachesPastBounds();
    }
    if (!matters) return true;
    Bounds box = Bounds::infinite();
    for (size_t i = 0; i < node.children.size(); ++i)
        if (uninverted(i)) box = box.intersected(node.children[i]->surfaceBounds());
    return rayMeetsBox(ray, tMin, box);
}

// The common part of the operands' inside regions of an intersection or
// difference (its subtracted operands inverted). An unbounded operand is
// bounded where the others bound it (Object::insideBoundsWithin: a
// quadric cylinder between two planes), so pieces made of quadrics and
// planes get a finite box and a place in the BVH instead of being tested
// by every ray.
Bounds operandsCommonBounds(const Object& node) {
    const size_t n = node.children.size();
    if (n == 0) return {};
    Bounds box = Bounds::infinite();
    for (size_t i = 0; i < n; ++i) box = box.intersected(operandInsideBounds(node, i));
    if (box.isEmpty() || box.isFinite()) return box;
    for (int pass = 0; pass < 2; ++pass)
        for (size_t i = 0; i < n; ++i) {
            if (node.op == CsgOp::Difference && i > 0) continue;
            box = box.intersected(node.children[i]->insideBoundsWithin(box));
            if (box.isEmpty()) return box;
        }
    return box;
}

bool hasPatchOperand(const Object& node) {
    return std::any_of(node.children.begin(), node.children.end(),
                       [](const ObjectRef& c) { return c->isPatch(); });
}

}  // namespace

void allHits(const Object& node, const Ray& ray, double tMin, double tMax, RayKind kind,
             std::vector<SurfaceHit>& hits, bool inverted) {
    if ((node.op == CsgOp::Intersection || node.op == CsgOp::Difference) &&
        !rayMeetsOperandBoxes(node, ray, tMin))
        return;
    const size_t from = hits.size();
    for (size_t i = 0; i < node.children.size(); ++i) {
        const size_t start = hits.size();
        // A difference inverts its later operands.
        const bool subtracted = node.op == CsgOp::Difference && i > 0;
        node.children[i]->allHits(ray, tMin, tMax, kind, hits, inverted != subtracted);
        if (node.op == CsgOp::Union && !inverted) continue;
        size_t kept = start;
        for (size_t r = start; r < hits.size(); ++r)
            if (keepsCrossing(node, i, ray.at(hits[r].t), inverted)) hits[kept++] = hits[r];
        hits.resize(kept);
    }
    // Stable: at equal t the earlier child comes first. Few hits are
    // sorted in place (std::stable_sort allocates a buffer every call).
    const auto first = hits.begin() + static_cast<std::ptrdiff_t>(from);
    if (hits.end() - first <= 32) {
        for (auto i = first + (first != hits.end() ? 1 : 0); i < hits.end(); ++i) {
            const SurfaceHit h = *i;
            auto j = i;
            for (; j > first && h.t < (j - 1)->t; --j) *j = *(j - 1);
            *j = h;
        }
    } else {
        std::stable_sort(first, hits.end(),
                         [](const SurfaceHit& a, const SurfaceHit& b) { return a.t < b.t; });
    }
}

namespace {

// A child's crossing awaiting its test: where it lies in the hit list and
// which child it belongs to.
struct Candidate {
    double t;
    uint32_t index, child;
};

}  // namespace

bool firstAccepted(const Object& node, const Ray& ray, double tMin, double tMax, RayKind kind,
                   bool inverted, bool (*accept)(const SurfaceHit&, const void* context),
                   const void* context, SurfaceHit& hit) {
    if ((node.op == CsgOp::Intersection || node.op == CsgOp::Difference) &&
        !rayMeetsOperandBoxes(node, ray, tMin))
        return false;
    ScratchVector<SurfaceHit> hitScratch;
    ScratchVector<Candidate> candidateScratch;
    std::vector<SurfaceHit>& hits = hitScratch.get();
    std::vector<Candidate>& order = candidateScratch.get();
    for (size_t i = 0; i < node.children.size(); ++i) {
        const size_t start = hits.size();
        const bool subtracted = node.op == CsgOp::Difference && i > 0;
        node.children[i]->allHits(ray, tMin, tMax, kind, hits, inverted != subtracted);
        for (size_t r = start; r < hits.size(); ++r)
            order.push_back({hits[r].t, static_cast<uint32_t>(r), static_cast<uint32_t>(i)});
    }
    // allHits' order: by t, at equal t the earlier child (and within a
    // child its own order) first.
    std::sort(order.begin(), order.end(), [](const Candidate& a, const Candidate& b) {
        return a.t < b.t || (a.t == b.t && a.index < b.index);
    });
    const bool keepsAll = node.op == CsgOp::Union && !inverted;
    for (const Candidate& c : order) {
        if (!keepsAll && !keepsCrossing(node, c.child, ray.at(c.t), inverted)) continue;
        if (!accept(hits[c.index], context)) continue;
        hit = hits[c.index];
        return true;
    }
    return false;
}

bool inside(const Object& node, const Vec3& p) {
    const auto& kids = node.children;
    switch (node.op) {
        case CsgOp::Union:
        case CsgOp::Merge:
            return std::any_of(kids.begin(), kids.end(),
                               [&](const ObjectRef& c) { return c->inside(p); });
        case CsgOp::Intersection:
            return std::all_of(kids.begin(), kids.end(),
                               [&](const ObjectRef& c) { return c->inside(p); });
        case CsgOp::Difference:
            if (kids.empty() || !kids[0]->inside(p)) return false;
            return std::all_of(kids.begin() + 1, kids.end(),
                               [&](const ObjectRef& c) { return c->insideInverted(p); });
    }
    return false;
}

Bounds surfaceBounds(const Object& node) {
    Bounds out;
    const size_t n = node.children.size();
    for (size_t i = 0; i < n; ++i) {
        const Object& child = *node.children[i];
        Bounds part = child.surfaceBounds();
        if (node.op == CsgOp::Intersection || node.op == CsgOp::Difference) {
            // A crossing survives intersection and difference only inside all
            // the other operands.
            for (size_t j = 0; j < n; ++j)
                if (j != i) part = part.intersected(operandInsideBounds(node, j));
            // An unbounded closed primitive (a plane) crosses only where its
            // own inside region ends: a plane { -y, 0 } operand bounds the
            // intersection from below, as povray's box of it is (measured
            // with min_extent on lights/glassthing's target).
            if (!part.isEmpty() && child.shape && !child.isPatch() &&
                !child.shape->bounds().isFinite())
                part = part.intersected(operandInsideBounds(node, i));
        }
        if (!part.isEmpty()) out.extend(part);
    }
    // Every surviving crossing is also inside its own operand (closed),
    // unless that operand is a patch, which encloses nothing.
    if ((node.op == CsgOp::Intersection || node.op == CsgOp::Difference) && !out.isFinite() &&
        !hasPatchOperand(node))
        out = out.intersected(operandsCommonBounds(node));
    return out;
}

Bounds insideBounds(const Object& node) {
    if (node.op == CsgOp::Union || node.op == CsgOp::Merge) {
        Bounds out;
        for (const ObjectRef& c : node.children) {
            const Bounds b = c->insideBounds();
            if (!b.isEmpty()) out.extend(b);
        }
        return out;
    }
    return operandsCommonBounds(node);
}

namespace {

ObjectRef inherit(const ObjectRef& obj, const std::shared_ptr<const Texture>& texture,
                  const Object& flags) {
    const bool needsTexture = !obj->texture && texture;
    const bool needsInterior = !obj->interior && flags.interior;
    const bool needsRegion =
        !obj->interior && !flags.interior && flags.regionKey && obj->regionKey != flags.regionKey;
    const bool needsInteriorTexture = !obj->interiorTexture && flags.interiorTexture;
    const bool needsFlags =
        (flags.noShadow && !obj->noShadow) || (flags.noImage && !obj->noImage) ||
        (flags.noReflection && !obj->noReflection) || (flags.noRadiosity && !obj->noRadiosity) ||
        (flags.radiosityImportance > 0 && obj->radiosityImportance == 0) ||
        (flags.doubleIlluminate && !obj->doubleIlluminate) || (flags.hollow && !obj->hollow);
    const bool needsPhotons = flags.photons.given && !obj->photons.given;
    if (!obj->isCsg() && !needsTexture && !needsInterior && !needsInteriorTexture && !needsFlags &&
        !needsPhotons && !needsRegion)
        return obj;
    auto copy = std::make_shared<Object>(*obj);
    // A CSG tree without interiors is one region, named by its top node.
    if (!copy->interior && !needsInterior)
        copy->regionKey = flags.regionKey ? flags.regionKey : copy->isCsg() ? copy.get() : nullptr;
    if (needsTexture) copy->texture = texture;
    if (needsInterior) copy->interior = flags.interior;
    if (needsInteriorTexture) copy->interiorTexture = flags.interiorTexture;
    copy->noShadow |= flags.noShadow;
    copy->noImage |= flags.noImage;
    copy->noReflection |= flags.noReflection;
    copy->noRadiosity |= flags.noRadiosity;
    if (copy->radiosityImportance == 0) copy->radiosityImportance = flags.radiosityImportance;
    copy->doubleIlluminate |= flags.doubleIlluminate;
    copy->hollow |= flags.hollow;
    if (needsPhotons) copy->photons = flags.photons;
    for (ObjectRef& child : copy->children) child = inherit(child, copy->texture, *copy);
    return copy;
}

}  // namespace

ObjectRef resolveInheritance(const ObjectRef& top) {
    return inherit(top, nullptr, Object{});
}

}  // namespace frameray::scene::csg
