// The basic shapes (seed 003 §5.2): sphere, box, plane, cylinder, cone,
// disc, triangle, smooth_triangle and quadric, each read after its '{'
// (the object's modifiers follow, parse_object.cpp).
#include <cmath>

#include "scene/flat_shapes.h"
#include "scene/quadric.h"
#include "scene/revolved_shapes.h"
#include "sdl/builders.h"

namespace frameray::sdl {

namespace {

// The commas between a shape's numbers are optional in povray (`box {
// <0,0,0> <1,1,1> }`): take one when it is there. `between` says where.
void comma(Reader& r, const char* /*between*/) {
    r.accept(Sym::Comma);
}

bool samePoint(const Vec3& a, const Vec3& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

}  // namespace

std::shared_ptr<const scene::Shape> parseSphere(BuildContext& c, const Token&) {
    Reader& r = c.reader;
    const Vec3 center = r.parseVec3();
    comma(r, "between the centre and the radius");
    return std::make_shared<scene::Sphere>(center, r.parseFloat());
}

std::shared_ptr<const scene::Shape> parseBox(BuildContext& c, const Token&) {
    Reader& r = c.reader;
    const Vec3 a = r.parseVec3();
    comma(r, "between the corners");
    return std::make_shared<scene::Box>(a, r.parseVec3());
}

std::shared_ptr<const scene::Shape> parsePlane(BuildContext& c, const Token&) {
    Reader& r = c.reader;
    const Token at = r.peek();
    const Vec3 n = r.parseVec3();
    if (length(n) == 0) r.fail(at, "the normal of a plane must not be zero");
    comma(r, "between the normal and the distance");
    return std::make_shared<scene::Plane>(n, r.parseFloat());
}

std::shared_ptr<const scene::Shape> parseCylinder(BuildContext& c, const Token& kind) {
    Reader& r = c.reader;
    const Vec3 base = r.parseVec3();
    comma(r, "between the base and the cap");
    const Vec3 cap = r.parseVec3();
    comma(r, "between the cap and the radius");
    const double radius = r.parseFloat();
    if (samePoint(base, cap)) r.fail(kind, "Degenerate cylinder, base point = apex point.");
    // `open` follows the numbers, before any modifier.
    const bool open = r.accept(Keyword::kw_open);
    return std::make_shared<scene::Cylinder>(base, cap, std::fabs(radius), open);
}

std::shared_ptr<const scene::Shape> parseCone(BuildContext& c, const Token& kind) {
    Reader& r = c.reader;
    const Vec3 base = r.parseVec3();
    comma(r, "between the base point and its radius");
    const double r1 = r.parseFloat();
    comma(r, "between the base radius and the cap point");
    const Vec3 cap = r.parseVec3();
    comma(r, "between the cap point and its radius");
    const double r2 = r.parseFloat();
    if (samePoint(base, cap)) r.fail(kind, "Degenerate cone/cylinder.");
    const bool open = r.accept(Keyword::kw_open);
    if (r1 == r2) return std::make_shared<scene::Cylinder>(base, cap, std::fabs(r1), open);
    return std::make_shared<scene::Cone>(base, std::fabs(r1), cap, std::fabs(r2), open);
}

std::shared_ptr<const scene::Shape> parseDisc(BuildContext& c, const Token&) {
    Reader& r = c.reader;
    const Vec3 center = r.parseVec3();
    comma(r, "between the centre and the normal");
    const Token at = r.peek();
    const Vec3 n = r.parseVec3();
    if (length(n) == 0) r.fail(at, "the normal of a disc must not be zero");
    comma(r, "between the normal and the radius");
    const double radius = r.parseFloat();
    double hole = 0;
    if (r.accept(Sym::Comma)) hole = r.parseFloat();
    return std::make_shared<scene::Disc>(center, n, radius, hole);
}

std::shared_ptr<const scene::Shape> parseTriangle(BuildContext& c, const Token& kind) {
    Reader& r = c.reader;
    Vec3 v[3];
    for (int i = 0; i < 3; ++i) {
        if (i) comma(r, "between the corners");
        v[i] = r.parseVec3();
    }
    auto tri = std::make_shared<scene::Triangle>(v[0], v[1], v[2]);
    if (tri->isDegenerate()) r.warn(kind, "Degenerate triangle. Please remove.");
    return tri;
}

std::shared_ptr<const scene::Shape> parseSmoothTriangle(BuildContext& c, const Token& kind) {
    Reader& r = c.reader;
    Vec3 v[3], n[3];
    for (int i = 0; i < 3; ++i) {
        if (i) comma(r, "between the corners");
        v[i] = r.parseVec3();
        comma(r, "between a corner and its normal");
        n[i] = r.parseVec3();
    }
    auto tri = std::make_shared<scene::SmoothTriangle>(v[0], n[0], v[1], n[1], v[2], n[2]);
    if (tri->isDegenerate()) r.warn(kind, "Degenerate triangle. Please remove.");
    return tri;
}

std::shared_ptr<const scene::Shape> parseQuadric(BuildContext& c, const Token&) {
    Reader& r = c.reader;
    const Vec3 sq = r.parseVec3();
    comma(r, "after the square terms <A,B,C>");
    const Vec3 mixed = r.parseVec3();
    comma(r, "after the mixed terms <D,E,F>");
    const Vec3 lin = r.parseVec3();
    comma(r, "after the linear terms <G,H,I>");
    const double j = r.parseFloat();
    return std::make_shared<scene::Quadric>(scene::Quadric::Coefficients{
        sq.x, sq.y, sq.z, mixed.x, mixed.y, mixed.z, lin.x, lin.y, lin.z, j});
}

}  // namespace frameray::sdl
