// A scene object (seed 003 §5.2-5.3): either a primitive — a shape placed
// by a transform — or a CSG node combining child objects; either kind with
// its texture and the object modifiers (inverse, clipped_by, bounded_by,
// no_shadow, ...).
//
// Transforms are pushed down to the primitives when applied (transformBy),
// as povray does, so every primitive carries its complete object-to-world
// transform and a hit on it can be shaded from the primitive alone. All
// queries below take and return world-space values.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "scene/clip_list.h"
#include "scene/interior.h"
#include "scene/lights.h"
#include "scene/photon_settings.h"
#include "scene/shapes.h"
#include "scene/texture.h"
#include "util/shared_transform.h"

namespace frameray::scene {

struct Object;
using ObjectRef = std::shared_ptr<const Object>;

// How a CSG node combines its children (scene/csg.h implements it).
enum class CsgOp { Union, Merge, Intersection, Difference };

// Which object flags hide a surface from a kind of ray.
enum class RayKind {
    Camera,      // skips no_image surfaces (also rays refracted from camera rays)
    Reflection,  // skips no_reflection surfaces
    Shadow,      // skips no_shadow surfaces
    Photon,      // skips no_shadow and no_image surfaces (povray 3.7's photons)
    Radiosity,   // skips no_radiosity surfaces
    Any,         // sees everything (bounding tests)
};

// The lights of a light_group (povray 3.7): they light only the objects of
// their group, which see the scene's own lights only when the outermost
// group says global_lights on. Every object casts shadows from every light.
struct LightGroup {
    std::vector<Light> lights;
    bool globalLights = false;
};

// A crossing of an object's surface: the ray parameter and the primitive
// whose surface it is (the one to shade: its normal, its texture).
struct SurfaceHit {
    double t = kInfinity;
    const Object* primitive = nullptr;
};

struct Object {
    // A primitive when `shape` is set, else a CSG node over `children`.
    std::shared_ptr<const Shape> shape;
    // Shared (16 bytes; the identity without an allocation): 10^6 objects
    // mostly keep the identity (issue 23).
    SharedTransform transform;  // primitives: object space -> world space
    CsgOp op = CsgOp::Union;
    std::vector<ObjectRef> children;

    // Null: the nearest ancestor's texture, finally the default texture
    // (resolved once the object is placed in the scene, see csg.h).
    std::shared_ptr<const Texture> texture;
    // interior_texture: the texture of the surface's inner side (seen where
    // the outward normal faces away from the viewer). Null: the nearest
    // ancestor's, finally `texture` (povray 3.7, measured).
    std::shared_ptr<const Texture> interiorTexture;
    // A blob whose components carry textures: one per component (null: the
    // object's own texture), blended at each point by how much each
    // component adds to the field there (povray 3.7: weights |field_i| /
    // sum |field_j|, measured). Empty for everything else.
    std::vector<std::shared_ptr<const Texture>> componentTextures;
    // Null: the nearest ancestor's interior, finally none (air, ior 1).
    // Primitives sharing one Interior are one region for refraction.
    std::shared_ptr<const Interior> interior;
    // Without an interior, inside which region of space a ray is between
    // this object's surfaces: every primitive of one CSG tree without
    // interiors is one region, as in povray, whose CSG children share their
    // parent's (default) interior (measured: a ray in glass entering a
    // cavity cut as `intersection { sphere box }` leaves it through the
    // box's face back into the glass). Set by csg::resolveInheritance;
    // null: the object alone.
    const void* regionKey = nullptr;
    bool inverse = false;
    // Only the parts of the surface inside every clipping object remain.
    ClipList clippedBy;
    // A camera ray that neither hits every bounding object nor starts
    // inside it skips this object (povray; shadow rays ignore the bound).
    std::vector<ObjectRef> boundedBy;
    bool noShadow = false;
    bool noImage = false;
    bool noReflection = false;
    bool noRadiosity = false;  // radiosity rays pass through it
    // radiosity { importance }: the share of `count` a sample on it shoots;
    // 0: not given (1).
    double radiosityImportance = 0;
    bool doubleIlluminate = false;  // lights reach the side facing away from them
    bool hollow = false;            // fog reaches rays inside it (povray's `hollow`)
    // Its part in photon mapping; a CSG node's block holds for the
    // children that have none (csg::resolveInheritance).
    ObjectPhotons photons;

    // (Light sources written inside a CSG node or light_group are the
    // parser's until the object is placed: sdl::ObjectLights.)
    // Set on the primitives of a light_group once placed: the lights that
    // shade them. Null: the scene's lights.
    std::shared_ptr<const LightGroup> lightGroup;

    bool isCsg() const { return !shape; }

    // Applies `t` after everything so far: to the primitive's transform or
    // to every child, to the clipping and bounding objects and to the
    // textures already attached (a transform after a texture moves it).
    // Shared children are copied, never modified.
    void transformBy(const Transform& t);

    // First surface crossing in (tMin, tMax) that `kind` rays see.
    bool firstHit(const Ray& ray, double tMin, double tMax, RayKind kind, SurfaceHit& hit) const;
    // Every surface crossing in (tMin, tMax), appended to `hits` in
    // increasing t (the caller's vector is used as scratch beyond its end).
    // `kind` only decides whether bounded_by applies (not to shadow rays);
    // the flags are firstHit's to check. `inverted`: the object is an
    // operand an odd number of inversions deep (povray inverts a union
    // into the intersection of its inverted operands, which hides the
    // crossings inside its other operands).
    void allHits(const Ray& ray, double tMin, double tMax, RayKind kind,
                 std::vector<SurfaceHit>& hits, bool inverted = false) const;
    // povray's inside test: the object's own region (toggled by inverse,
    // except for patches, which enclose nothing) within every clip.
    bool inside(const Vec3& p) const;
    // As inside(), for this object used inverted (a subtracted operand of
    // a difference).
    bool insideInverted(const Vec3& p) const;
    // Unit normal of a primitive's surface at a world point on it.
    Vec3 normalAt(const Vec3& p) const;
    // uv_mapping's point (u, v, 0) for a world point on a primitive's
    // surface: the shape's own uv, else the point's world x and y (povray
    // 3.7, measured).
    Vec3 surfaceUv(const Vec3& p) const {
        double u = 0, v = 0;
        if (shape && shape->uv(transform.inversePoint(p), u, v)) return Vec3(u, v, 0);
        return Vec3(p.x, p.y, 0);
    }
    // normalAt(p) and surfaceUv(p) at once (equal results; meshes search
    // the point's triangle once).
    Vec3 normalAndUvAt(const Vec3& p, Vec3& uv) const {
        const Vec3 q = transform.inversePoint(p);
        bool hasUv = false;
        double u = 0, v = 0;
        const Vec3 n = shape->worldNormalUv(q, transform, hasUv, u, v);
        uv = hasUv ? Vec3(u, v, 0) : Vec3(p.x, p.y, 0);
        return n;
    }
    // The textures colouring world point p and their weights (summing to
    // 1): `own` (the object's resolved texture) alone, except for a blob
    // with componentTextures.
    void visitTextures(const Vec3& p, const Texture& own,
                       const std::function<void(const Texture&, double)>& visit) const;

    // Conservative world bounds of what a ray can hit, and of where
    // inside() can be true. Empty when there is nothing; infinite when
    // unbounded.
    Bounds surfaceBounds() const;
    Bounds insideBounds() const;
    // insideBounds() within the world box `box`, tighter where the shape
    // can use the box (Shape::insideBoundsWithin).
    Bounds insideBoundsWithin(const Bounds& box) const;
    // The bounding box the SDL reports (min_extent, max_extent).
    Bounds worldBounds() const { return surfaceBounds(); }
    // Bounds of insideInverted(): infinite, or empty for patches.
    Bounds insideInvertedBounds() const;
    // Whether nothing can ever be inside, inverted or not (patches, and
    // CSG built from them only in ways that keep this).
    bool isPatch() const;
    bool warnsAsPatch() const;
};

}  // namespace frameray::scene
