// CSG trees and object modifiers in world space: which crossings survive,
// which primitive is reported, inside tests, bounds, inheritance, and the
// SDL that builds them.
#include "scene/csg.h"

#include <gtest/gtest.h>

#include <random>

#include "parse_support.h"
#include "render/world.h"
#include "scene/flat_shapes.h"
#include "scene/quadric.h"
#include "scene/revolved_shapes.h"
#include "sdl/interpreter.h"

using namespace frameray;
using namespace frameray::scene;

namespace {

std::shared_ptr<Object> primitive(std::shared_ptr<const Shape> shape) {
    auto o = std::make_shared<Object>();
    o->shape = std::move(shape);
    return o;
}
std::shared_ptr<Object> sphere(const Vec3& c, double r) {
    return primitive(std::make_shared<Sphere>(c, r));
}
std::shared_ptr<Object> box(const Vec3& a, const Vec3& b) {
    return primitive(std::make_shared<Box>(a, b));
}

std::shared_ptr<Object> csgOf(CsgOp op, std::vector<ObjectRef> kids) {
    auto o = std::make_shared<Object>();
    o->op = op;
    o->children = std::move(kids);
    return o;
}

std::vector<SurfaceHit> allHits(const Object& o, const Ray& r) {
    std::vector<SurfaceHit> h;
    o.allHits(r, 0, kInfinity, RayKind::Camera, h);
    return h;
}

const Ray kAlongX{{-10, 0, 0}, {1, 0, 0}};

}  // namespace

TEST(Csg, UnionKeepsEveryCrossing) {
    auto a = sphere({-1, 0, 0}, 2), b = sphere({1, 0, 0}, 2);
    auto u = csgOf(CsgOp::Union, {a, b});
    const auto h = allHits(*u, kAlongX);
    ASSERT_EQ(h.size(), 4u);
    EXPECT_DOUBLE_EQ(h[0].t, 7);
    EXPECT_EQ(h[0].primitive, a.get());
    EXPECT_DOUBLE_EQ(h[1].t, 9);
    EXPECT_EQ(h[1].primitive, b.get());
    EXPECT_DOUBLE_EQ(h[2].t, 11);
    EXPECT_DOUBLE_EQ(h[3].t, 13);
    EXPECT_TRUE(u->inside({2.5, 0, 0}));
    SurfaceHit first;
    ASSERT_TRUE(u->firstHit(kAlongX, 0, kInfinity, RayKind::Camera, first));
    EXPECT_EQ(first.primitive, a.get());
}

TEST(Csg, MergeDropsInnerSurfaces) {
    auto m = csgOf(CsgOp::Merge, {sphere({-1, 0, 0}, 2), sphere({1, 0, 0}, 2)});
    const auto h = allHits(*m, kAlongX);
    ASSERT_EQ(h.size(), 2u);
    EXPECT_DOUBLE_EQ(h[0].t, 7);
    EXPECT_DOUBLE_EQ(h[1].t, 13);
}

TEST(Csg, IntersectionAndDifference) {
    auto a = sphere({-1, 0, 0}, 2), b = sphere({1, 0, 0}, 2);
    auto i = csgOf(CsgOp::Intersection, {a, b});
    auto h = allHits(*i, kAlongX);
    ASSERT_EQ(h.size(), 2u);
    EXPECT_DOUBLE_EQ(h[0].t, 9);  // b's near side, inside a
    EXPECT_EQ(h[0].primitive, b.get());
    EXPECT_DOUBLE_EQ(h[1].t, 11);
    EXPECT_EQ(h[1].primitive, a.get());
    EXPECT_TRUE(i->inside({0, 0, 0}));
    EXPECT_FALSE(i->inside({-2, 0, 0}));

    auto d = csgOf(CsgOp::Difference, {a, b});
    h = allHits(*d, kAlongX);
    ASSERT_EQ(h.size(), 2u);
    EXPECT_DOUBLE_EQ(h[0].t, 7);
    EXPECT_DOUBLE_EQ(h[1].t, 9);  // the bite: b's surface, inside a
    EXPECT_EQ(h[1].primitive, b.get());
    EXPECT_TRUE(d->inside({-2, 0, 0}));
    EXPECT_FALSE(d->inside({0, 0, 0}));
    // Bounds: the difference is within its first operand.
    const Bounds db = d->surfaceBounds();
    EXPECT_DOUBLE_EQ(db.lo.x, -3);
    EXPECT_DOUBLE_EQ(db.hi.x, 1);
}

TEST(Csg, CoincidentBoxFacesFollowPovray) {
    // difference { box { -1, 1 } box { <-0.5,0,-0.5>, <0.5,1,0.5> } }:
    // povray keeps a lid over the pit (the subtracted box's top face).
    auto outer = box({-1, -1, -1}, {1, 1, 1}), pit = box({-0.5, 0, -0.5}, {0.5, 1, 0.5});
    auto d = csgOf(CsgOp::Difference, {outer, pit});
    SurfaceHit h;
    ASSERT_TRUE(d->firstHit({{0.1, 5, 0.2}, {0, -1, 0}}, 0, kInfinity, RayKind::Camera, h));
    EXPECT_DOUBLE_EQ(h.t, 4);
    // Two boxes sharing a face intersect in that face (box faces are inside).
    auto i =
        csgOf(CsgOp::Intersection, {box({-1, -1, -1}, {1, 0, 1}), box({-1, 0, -1}, {1, 1, 1})});
    ASSERT_TRUE(i->firstHit({{0.1, 5, 0.2}, {0, -1, 0}}, 0, kInfinity, RayKind::Camera, h));
    EXPECT_DOUBLE_EQ(h.t, 5);
}

TEST(Csg, InverseAndPatches) {
    auto s = sphere({0, 0, 0}, 1);
    s->inverse = true;
    EXPECT_FALSE(s->inside({0, 0, 0}));
    EXPECT_TRUE(s->inside({5, 0, 0}));
    EXPECT_TRUE(s->insideInverted({0, 0, 0}));
    EXPECT_FALSE(s->insideBounds().isFinite());
    // The surface is still the sphere.
    EXPECT_EQ(allHits(*s, kAlongX).size(), 2u);
    // A triangle is never inside, inverted or not: difference { sphere
    // triangle } keeps none of the sphere (povray).
    auto tri =
        primitive(std::make_shared<Triangle>(Vec3{-5, 0, -5}, Vec3{5, 0, -5}, Vec3{0, 0, 5}));
    EXPECT_FALSE(tri->insideInverted({0, 1, 0}));
    auto d = csgOf(CsgOp::Difference, {sphere({0, 0, 0}, 1), tri});
    const auto h = allHits(*d, {{0.1, 5, 0.1}, {0, -1, 0}});
    ASSERT_EQ(h.size(), 1u);  // only the triangle, inside the sphere
    EXPECT_EQ(h[0].primitive, tri.get());
    EXPECT_DOUBLE_EQ(h[0].t, 5);
}

TEST(Csg, TransformsReachEveryPrimitiveAndCopyShared) {
    auto a = sphere({0, 0, 0}, 1);
    auto u = csgOf(CsgOp::Union, {a, sphere({3, 0, 0}, 1)});
    auto moved = std::make_shared<Object>(*u);
    moved->transformBy(Transform::translate({0, 10, 0}));
    SurfaceHit h;
    ASSERT_TRUE(moved->firstHit({{0, 20, 0}, {0, -1, 0}}, 0, kInfinity, RayKind::Camera, h));
    EXPECT_DOUBLE_EQ(h.t, 9);
    EXPECT_NE(h.primitive, a.get());  // a transformed copy, the original untouched
    ASSERT_TRUE(u->firstHit({{0, 20, 0}, {0, -1, 0}}, 0, kInfinity, RayKind::Camera, h));
    EXPECT_EQ(h.primitive, a.get());
    EXPECT_DOUBLE_EQ(h.t, 19);
    // The normal comes from the primitive's own transform.
    const Vec3 n = h.primitive->normalAt({0, 1, 0});
    EXPECT_DOUBLE_EQ(n.y, 1);
}

TEST(Csg, ClippedByKeepsOnlyCrossingsInsideTheClip) {
    auto s = sphere({0, 0, 0}, 2);
    s->clippedBy = {primitive(std::make_shared<Plane>(Vec3{1, 0, 0}, 0))};  // keep x < 0
    auto h = allHits(*s, kAlongX);
    ASSERT_EQ(h.size(), 1u);
    EXPECT_DOUBLE_EQ(h[0].t, 8);
    EXPECT_FALSE(s->inside({1, 0, 0}));
    EXPECT_TRUE(s->inside({-1, 0, 0}));
    // Inverting a clipped object does not invert its clip (povray).
    EXPECT_FALSE(s->insideInverted({1, 0, 0}));
    EXPECT_TRUE(s->insideInverted({-3, 0, 0}));
    const Bounds b = s->surfaceBounds();
    EXPECT_DOUBLE_EQ(b.lo.x, -2);
    EXPECT_DOUBLE_EQ(b.hi.x, 1e-10);
}

// The clip list's box, computed once when the list is made (issue 23),
// is the common part of its non-inverted clips' boxes, and moves with the
// object: a clipped object translated sees rays only where the moved clip is.
TEST(Csg, ClipListBoxIsItsClipsCommonBoxAndMovesWithTheObject) {
    auto s = sphere({0, 0, 0}, 1.2);
    auto inverted = box({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5});
    inverted->inverse = true;
    s->clippedBy = {box({-1, -1, -1}, {1, 1, 1}), box({0, -3, -3}, {3, 3, 3}), inverted};
    const Bounds b = s->clippedBy.box();
    EXPECT_EQ(b.lo.x, 0);
    EXPECT_EQ(b.hi.x, 1);
    EXPECT_EQ(b.lo.y, -1);
    EXPECT_EQ(b.hi.z, 1);
    EXPECT_EQ(ClipList{}.box().lo.x, -kInfinity);
    EXPECT_EQ(ClipList{inverted}.box().hi.x, kInfinity);

    auto moved = std::make_shared<Object>(*s);
    moved->transformBy(Transform::translate({0, 10, 0}));
    EXPECT_EQ(moved->clippedBy.size(), 3u);
    EXPECT_EQ(moved->clippedBy.box().lo.y, 9);
    EXPECT_EQ(moved->clippedBy.box().hi.y, 11);
    EXPECT_EQ(s->clippedBy.box().lo.y, -1);  // the original's list untouched
    // Rays through the moved clip's box see the moved sphere's surface
    // where it is inside every clip (x in [0, 1]).
    const Ray down{{0.5, 20, 0.5}, {0, -1, 0}};
    EXPECT_EQ(allHits(*moved, down).size(), 2u);
    const Ray across{{-5, 10, 0.8}, {1, 0, 0}};
    ASSERT_EQ(allHits(*moved, across).size(), 1u);
    EXPECT_GT(allHits(*moved, across)[0].t, 5);
}

// An infinite quadric cylinder (x^2 + z^2 = 1, as shapes.inc's
// Cylinder_Y) or hyperboloid (x^2 - y^2 + z^2 = 1) cut by two planes: the
// intersection's box is finite (so it joins the BVH), and holds every
// crossing. Scaled and moved, as chess2's pieces are.
TEST(Csg, QuadricBetweenPlanesHasFiniteBounds) {
    auto cylinder =
        primitive(std::make_shared<Quadric>(Quadric::Coefficients{1, 0, 1, 0, 0, 0, 0, 0, 0, -1}));
    auto hyperboloid =
        primitive(std::make_shared<Quadric>(Quadric::Coefficients{1, -1, 1, 0, 0, 0, 0, 0, 0, -1}));
    for (const auto& q : {cylinder, hyperboloid}) {
        EXPECT_FALSE(q->insideBounds().isFinite());
        auto shape =
            csgOf(CsgOp::Intersection, {primitive(std::make_shared<Plane>(Vec3{0, 1, 0}, 3)), q,
                                        primitive(std::make_shared<Plane>(Vec3{0, -1, 0}, -1))});
        shape->transformBy(Transform::scale({2, 1, 2}).then(Transform::translate({10, 0, -5})));
        const Bounds b = shape->surfaceBounds();
        ASSERT_TRUE(b.isFinite());
        EXPECT_TRUE(shape->insideBounds().isFinite());
        // Radius 2 (cylinder) or 2 sqrt(1 + 3^2) (hyperboloid at y = 3).
        const double r = q == cylinder ? 2 : 2 * std::sqrt(10.0);
        EXPECT_NEAR(b.lo.x, 10 - r, 1e-6);
        EXPECT_NEAR(b.hi.x, 10 + r, 1e-6);
        EXPECT_NEAR(b.lo.z, -5 - r, 1e-6);
        EXPECT_NEAR(b.hi.z, -5 + r, 1e-6);
        EXPECT_NEAR(b.lo.y, 1, 1e-6);
        EXPECT_NEAR(b.hi.y, 3, 1e-6);
        // Every crossing of rays through the piece lies in the box.
        for (double y = 1.1; y < 3; y += 0.3)
            for (const auto& h : allHits(*shape, {{-20, y, -5}, {1, 0, 0}})) {
                const Vec3 p = Vec3(-20, y, -5) + Vec3(1, 0, 0) * h.t;
                EXPECT_GE(p.x, b.lo.x);
                EXPECT_LE(p.x, b.hi.x);
            }
    }
    // A difference keeps its first operand's bound; an inverted cylinder
    // bounds nothing.
    auto inverted =
        primitive(std::make_shared<Quadric>(Quadric::Coefficients{1, 0, 1, 0, 0, 0, 0, 0, 0, -1}));
    inverted->inverse = true;
    auto open =
        csgOf(CsgOp::Intersection, {primitive(std::make_shared<Plane>(Vec3{0, 1, 0}, 3)), inverted,
                                    primitive(std::make_shared<Plane>(Vec3{0, -1, 0}, -1))});
    EXPECT_FALSE(open->surfaceBounds().isFinite());
}

// intersection { box plane { -y, 0.001 } } (lights/glassthing's target):
// the plane cuts the box's bound at y = -0.001, as povray's min_extent
// says. The plane's own crossings lie only where its inside ends.
TEST(Csg, PlaneOperandClipsIntersectionBounds) {
    auto cut = csgOf(
        CsgOp::Intersection,
        {box({-1, -2, -1}, {1, 2, 1}), primitive(std::make_shared<Plane>(Vec3{0, -1, 0}, 0.001))});
    const Bounds b = cut->surfaceBounds();
    EXPECT_NEAR(b.lo.y, -0.001, 1e-9);
    EXPECT_DOUBLE_EQ(b.hi.y, 2);
    EXPECT_DOUBLE_EQ(b.lo.x, -1);
    EXPECT_DOUBLE_EQ(b.hi.x, 1);
}

TEST(Csg, BoundedBySkipsRaysThatMissTheBound) {
    auto s = sphere({0, 0, 0}, 2);
    s->boundedBy = {box({-1, -1, -1}, {1, 1, 1})};  // smaller than the sphere
    EXPECT_EQ(allHits(*s, kAlongX).size(), 2u);
    EXPECT_TRUE(allHits(*s, {{-10, 1.5, 0}, {1, 0, 0}}).empty());
    // Shadows are cast by the whole sphere (povray), so its bounds stay.
    SurfaceHit h;
    EXPECT_TRUE(s->firstHit({{-10, 1.5, 0}, {1, 0, 0}}, 0, kInfinity, RayKind::Shadow, h));
    const Bounds b = s->surfaceBounds();
    EXPECT_DOUBLE_EQ(b.hi.x, 2);
}

TEST(Csg, NoShadowChildHidesOnlyItselfFromShadowRays) {
    auto a = sphere({-3, 0, 0}, 1), b = sphere({3, 0, 0}, 1);
    b->noShadow = true;
    auto u = csg::resolveInheritance(csgOf(CsgOp::Union, {a, b}));
    SurfaceHit h;
    EXPECT_TRUE(u->firstHit({{-3, 5, 0}, {0, -1, 0}}, 0, kInfinity, RayKind::Shadow, h));
    EXPECT_FALSE(u->firstHit({{3, 5, 0}, {0, -1, 0}}, 0, kInfinity, RayKind::Shadow, h));
    EXPECT_TRUE(u->firstHit({{3, 5, 0}, {0, -1, 0}}, 0, kInfinity, RayKind::Camera, h));
}

TEST(Csg, ChildrenInheritTextureAndFlags) {
    auto red = std::make_shared<Texture>();
    red->pigment = std::make_shared<Pigment>(Color(RGB(1, 0, 0)));
    auto green = std::make_shared<Texture>();
    green->pigment = std::make_shared<Pigment>(Color(RGB(0, 1, 0)));
    auto plain = sphere({0, 0, 0}, 1);
    auto own = sphere({3, 0, 0}, 1);
    own->texture = green;
    auto inner = csgOf(CsgOp::Union, {plain, own});
    auto outer = csgOf(CsgOp::Union, {inner});
    outer->texture = red;
    outer->noShadow = true;
    const ObjectRef placed = csg::resolveInheritance(outer);
    const Object& placedInner = *placed->children[0];
    EXPECT_EQ(placedInner.children[0]->texture, red);
    EXPECT_EQ(placedInner.children[1]->texture, green);
    EXPECT_TRUE(placedInner.children[1]->noShadow);
    EXPECT_FALSE(plain->texture);  // the declared tree is untouched
}

TEST(World, CsgHitReportsTheChildPrimitive) {
    Scene s;
    auto a = box({-1, -1, -1}, {1, 1, 1});
    auto cut = sphere({0, 0, -1}, 0.5);
    s.objects = {csg::resolveInheritance(csgOf(CsgOp::Difference, {a, cut}))};
    render::World w(s);
    render::Hit hit;
    ASSERT_TRUE(w.intersect({{0, 0, -5}, {0, 0, 1}}, 0, kInfinity, hit));
    EXPECT_DOUBLE_EQ(hit.t, 4.5);  // the bottom of the bite
    ASSERT_TRUE(hit.object->shape);
    EXPECT_STREQ(hit.object->shape->name(), "sphere");
    ASSERT_TRUE(w.intersect({{0.9, 0, -5}, {0, 0, 1}}, 0, kInfinity, hit));
    EXPECT_DOUBLE_EQ(hit.t, 4);
    EXPECT_STREQ(hit.object->shape->name(), "box");
}

// --- SDL ---------------------------------------------------------------------

namespace {

using Parsed = test_support::ParsedScene;
std::string parseError(const std::string& text) {
    return test_support::parseErrorOf(text);
}

}  // namespace

TEST(CsgSdl, ShapesCsgAndModifiersParse) {
    Parsed p(R"(
        #declare U = union { sphere { 0, 1 } cylinder { 0, y, 0.5 pigment { rgb <0,1,0> } } pigment { rgb <1,0,0> } }
        object { U pigment { rgb <0,0,1> } translate x }
        difference { box { -1, 1 } cone { -2*y, 0.5, 2*y, 0.2 open } inverse }
        disc { 0, y, 2, 1 clipped_by { plane { x, 0 } } bounded_by { clipped_by } }
        triangle { 0, x, y double_illuminate }
        smooth_triangle { 0, -z, x, -z, y, -z no_shadow }
        quadric { <1,1,1>, 0, 0, -1 hollow }
    )");
    ASSERT_EQ(p.scene.objects.size(), 6u);
    const Object& u = *p.scene.objects[0];
    ASSERT_TRUE(u.isCsg());
    ASSERT_EQ(u.children.size(), 2u);
    // The untextured child takes the object's (recoloured) texture.
    EXPECT_EQ(u.children[0]->texture->pigment->solidColor().rgb.b, 1);
    EXPECT_EQ(u.children[1]->texture->pigment->solidColor().rgb.g, 1);
    EXPECT_DOUBLE_EQ(u.children[1]->transform.point({0, 0, 0}).x, 1);
    EXPECT_EQ(p.scene.objects[1]->op, CsgOp::Difference);
    EXPECT_TRUE(p.scene.objects[1]->inverse);
    EXPECT_EQ(p.scene.objects[2]->clippedBy.size(), 1u);
    EXPECT_EQ(p.scene.objects[2]->boundedBy.size(), 1u);
    EXPECT_TRUE(p.scene.objects[3]->doubleIlluminate);
    EXPECT_TRUE(p.scene.objects[4]->noShadow);
    EXPECT_STREQ(p.scene.objects[5]->shape->name(), "quadric");
}

TEST(CsgSdl, PovrayErrorsAndWarnings) {
    EXPECT_NE(parseError("cylinder { 0, 0, 1 }").find("Degenerate cylinder"), std::string::npos);
    EXPECT_NE(parseError("cone { y, 1, y, 0.5 }").find("Degenerate cone/cylinder"),
              std::string::npos);
    EXPECT_NE(
        parseError("union { sphere { 0, 1 } translate x sphere { 0, 1 } }").find("No matching }"),
        std::string::npos);
    EXPECT_NE(parseError("ovus { 1, 0.5 }").find("not supported yet: ovus"), std::string::npos);
    // media is supported, every sampling method included (issue 25).
    EXPECT_EQ(parseError("sphere { 0, 1 interior { media { } } }"), "");
    EXPECT_EQ(parseError("sphere { 0, 1 interior { media { method 1 } } }"), "");
    EXPECT_EQ(parseError("sphere { 0, 1 interior { media { method 2 } } }"), "");
    EXPECT_NE(parseError("sphere { 0, 1 interior { media { method 4 } } }")
                  .find("Unknown media sampling method"),
              std::string::npos);
    Parsed one(
        "union { sphere { 0, 1 } }  triangle { 0, x, 2*x }  difference { sphere { 0, 1 } triangle "
        "{ 0, x, y } }");
    EXPECT_NE(one.sink.warnings.find("Patch objects not allowed in intersection."),
              std::string::npos);
    EXPECT_NE(one.sink.warnings.find("Should have at least 2 objects in csg."), std::string::npos);
    EXPECT_NE(one.sink.warnings.find("Degenerate triangle. Please remove."), std::string::npos);
}

TEST(Csg, IntersectionWithADiscOnlyAlongRaysThroughItsBox) {
    // povray: intersection { disc { 0, y, 2 } box { -1, 1 } } seen edge-on
    // keeps the box's front face only in the disc's 0.001-thin bounding box
    // (the disc's inside is the half-space below it).
    auto disc = primitive(std::make_shared<Disc>(Vec3{0, 0, 0}, Vec3{0, 1, 0}, 2, 0));
    auto i = csgOf(CsgOp::Intersection, {disc, box({-1, -1, -1}, {1, 1, 1})});
    SurfaceHit h;
    ASSERT_TRUE(i->firstHit({{0, -0.0005, -5}, {0, 0, 1}}, 0, kInfinity, RayKind::Camera, h));
    EXPECT_DOUBLE_EQ(h.t, 4);
    EXPECT_FALSE(i->firstHit({{0, -0.5, -5}, {0, 0, 1}}, 0, kInfinity, RayKind::Camera, h));
    // From above, through the disc: the disc inside the box, then the box's
    // bottom (below the disc, so inside its half-space).
    const auto hits = allHits(*i, {{0.5, 5, 0}, {0, -1, 0}});
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_DOUBLE_EQ(hits[0].t, 5);
    EXPECT_DOUBLE_EQ(hits[1].t, 6);
    // A ray that misses the common box of both operands (the slab
    // [-1,1] x [-0.001,0.001] x [-1,1]) sees nothing, even one through the
    // disc towards a part of the box below the disc's plane.
    EXPECT_TRUE(allHits(*i, {{-10, -3.5, 0}, {1, 1, 0}}).empty());
    EXPECT_TRUE(allHits(*i, {{1.6, 0.5, 0}, {-1, -1, 0}}).empty());
}

// Object::firstHit on a CSG node searches the children's crossings lazily
// (inside tests only up to the crossing taken): it must give what allHits
// followed by a search for the first crossing the ray kind sees gives, for
// every operation, inverted operands, clips and hidden primitives.
TEST(Csg, FirstHitIsTheFirstVisibleCrossingOfAllHits) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> coord(-1.5, 1.5), radius(0.4, 1.4);
    auto randomPrimitive = [&](int n) -> std::shared_ptr<Object> {
        const Vec3 c{coord(rng), coord(rng), coord(rng)};
        auto o = n % 2 ? sphere(c, radius(rng)) : box(c - Vec3(radius(rng)), c + Vec3(radius(rng)));
        o->noShadow = n % 5 == 0;
        o->inverse = n % 7 == 3;
        return o;
    };
    const CsgOp ops[] = {CsgOp::Union, CsgOp::Merge, CsgOp::Intersection, CsgOp::Difference};
    int found = 0;
    for (int tree = 0; tree < 60; ++tree) {
        std::vector<ObjectRef> kids;
        for (int k = 0; k < 2 + tree % 3; ++k) {
            if (k == 1) {  // a nested node among the operands
                kids.push_back(csgOf(ops[(tree + 1) % 4], {randomPrimitive(tree + k),
                                                           randomPrimitive(tree + 2 * k + 1)}));
            } else {
                kids.push_back(randomPrimitive(tree * 3 + k));
            }
        }
        auto node = csgOf(ops[tree % 4], kids);
        node->inverse = tree % 9 == 4;
        if (tree % 4 == 1)
            node->clippedBy = {primitive(std::make_shared<Plane>(Vec3{0.3, 1, 0.2}, 0.4))};
        for (int r = 0; r < 200; ++r) {
            const Vec3 o{coord(rng) * 3, coord(rng) * 3, -6};
            const Ray ray{o, normalize(Vec3{coord(rng), coord(rng), 4})};
            for (const RayKind kind : {RayKind::Camera, RayKind::Shadow}) {
                std::vector<SurfaceHit> hits;
                node->allHits(ray, 1e-6, kInfinity, kind, hits);
                const SurfaceHit* expected = nullptr;
                for (const SurfaceHit& h : hits)
                    if (kind != RayKind::Shadow || !h.primitive->noShadow) {
                        expected = &h;
                        break;
                    }
                SurfaceHit got;
                const bool hit = node->firstHit(ray, 1e-6, kInfinity, kind, got);
                ASSERT_EQ(hit, expected != nullptr) << "tree " << tree << " ray " << r;
                if (!hit) continue;
                ++found;
                EXPECT_EQ(got.t, expected->t) << "tree " << tree << " ray " << r;
                EXPECT_EQ(got.primitive, expected->primitive) << "tree " << tree << " ray " << r;
            }
        }
    }
    EXPECT_GT(found, 800);
}
