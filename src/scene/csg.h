// Constructive solid geometry (seed 003 §5.3): how a CSG node's children
// combine into one surface and one inside, and how a finished tree hands
// its texture and flags down to its primitives.
//
// Every child contributes the crossings of its own surface that lie on
// the combined boundary, decided with the other children's inside tests
// at the crossing point:
//   union        all crossings (the inner surfaces stay)
//   merge        crossings not inside any other child
//   intersection crossings inside every other child
//   difference   intersection of the first child with the others inverted
#pragma once

#include <vector>

#include "scene/object.h"

namespace frameray::scene::csg {

// The crossings of a CSG node's combined surface in (tMin, tMax),
// appended to `hits` in increasing t. The node's own modifiers (inverse,
// clipped_by, bounded_by) are the caller's (Object) to apply; `inverted`:
// the node counts inverted (its own inverse included), as in Object::allHits.
void allHits(const Object& node, const Ray& ray, double tMin, double tMax, RayKind kind,
             std::vector<SurfaceHit>& hits, bool inverted);
// The first of allHits' crossings, nearest first, that `accept` takes
// (called with `context`); false when none. Equal to allHits followed by
// a search of its list, but a crossing's place on the combined boundary
// (the other operands' inside tests) is decided only for the crossings up
// to the one taken: a shadow ray through a CSG tests one or two, not all.
bool firstAccepted(const Object& node, const Ray& ray, double tMin, double tMax, RayKind kind,
                   bool inverted, bool (*accept)(const SurfaceHit&, const void* context),
                   const void* context, SurfaceHit& hit);
// The combined inside test, before the node's inverse and clips.
bool inside(const Object& node, const Vec3& p);
// Bounds of the combined surface and inside, before the node's modifiers.
Bounds surfaceBounds(const Object& node);
Bounds insideBounds(const Object& node);

// A top-level object ready to render: each primitive without a texture
// (or interior) gets its nearest ancestor's, and the flags set on a CSG node
// (no_shadow, no_image, no_reflection, double_illuminate, a photons block)
// hold for every primitive below it. Done when the object is placed in the scene, not
// when a CSG is declared: `object { U pigment { ... } }` recolours the
// untextured children of U (as povray does).
ObjectRef resolveInheritance(const ObjectRef& top);

}  // namespace frameray::scene::csg
