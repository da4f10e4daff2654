#include "scene/blob.h"

#include <algorithm>
#include <cmath>

#include "scene/polynomial_shapes.h"
#include "scene/scratch.h"
#include "scene/shape_math.h"
#include "util/roots.h"

namespace frameray::scene {

namespace {

// The point of segment [a, b] nearest p.
Vec3 nearestOnSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 w = b - a;
    const double ww = dot(w, w);
    if (ww == 0) return a;
    const double h = std::clamp(dot(p - a, w) / ww, 0.0, 1.0);
    return a + w * h;
}

// One piece of one component's field along the ray: over [lo, hi] it is
// the quartic c[0] + c[1] s + ... + c[4] s⁴.
struct FieldPiece {
    double lo, hi;
    double c[5];
    double peak;  // the largest value the piece takes anywhere on the ray
};

// Adds the piece of strength * (1 - |f + s g|²/R²)² over the part of
// [lo, hi] where |f + s g| < R.
void addPiece(const Vec3& f, const Vec3& g, double radius, double strength, double lo, double hi,
              std::vector<FieldPiece>& pieces) {
    double s1, s2;
    const double r2 = radius * radius;
    if (!detail::distanceRoots(f, g, r2, s1, s2)) return;
    lo = std::max(lo, s1);
    hi = std::min(hi, s2);
    if (!(lo < hi)) return;
    // e(s) = 1 - d²(s)/R² = e0 + e1 s + e2 s²; the field is strength * e².
    const double e0 = 1 - dot(f, f) / r2;
    const double e1 = -2 * dot(f, g) / r2;
    const double e2 = -dot(g, g) / r2;
    // e peaks where the ray passes closest to the component (e2 < 0 here:
    // distanceRoots found a chord, so g is not zero).
    const double ePeak = e0 - e1 * e1 / (4 * e2);
    FieldPiece piece{lo, hi, {}, strength * ePeak * ePeak};
    piece.c[0] = strength * e0 * e0;
    piece.c[1] = strength * 2 * e0 * e1;
    piece.c[2] = strength * (e1 * e1 + 2 * e0 * e2);
    piece.c[3] = strength * 2 * e1 * e2;
    piece.c[4] = strength * e2 * e2;
    pieces.push_back(piece);
}

// The pieces of a component's field along base + s dir (blob space).
void componentPieces(const Blob::Component& comp, const Vec3& base, const Vec3& dir,
                     std::vector<FieldPiece>& pieces) {
    const Vec3 f0 = comp.transformed ? comp.toBlob.inversePoint(base) : base;
    const Vec3 g = comp.transformed ? comp.toBlob.inverseDirection(dir) : dir;
    constexpr double kAll = kInfinity;
    if (comp.kind == Blob::Component::Kind::Sphere) {
        addPiece(f0 - comp.a, g, comp.radius, comp.strength, -kAll, kAll, pieces);
        return;
    }
    // Capsule: the distance is to end a where the axis coordinate h < 0, to
    // the axis for 0 <= h <= L, to end b beyond L.
    const Vec3 w = comp.b - comp.a;
    const double length = std::sqrt(dot(w, w));
    if (length == 0) {
        addPiece(f0 - comp.a, g, comp.radius, comp.strength, -kAll, kAll, pieces);
        return;
    }
    const Vec3 axis = w / length;
    const Vec3 f = f0 - comp.a;
    const double h0 = dot(f, axis), h1 = dot(g, axis);
    const Vec3 fPerp = f - axis * h0;
    const Vec3 gPerp = g - axis * h1;
    if (h1 == 0) {
        if (h0 < 0)
            addPiece(f, g, comp.radius, comp.strength, -kAll, kAll, pieces);
        else if (h0 > length)
            addPiece(f - w, g, comp.radius, comp.strength, -kAll, kAll, pieces);
        else
            addPiece(fPerp, gPerp, comp.radius, comp.strength, -kAll, kAll, pieces);
        return;
    }
    const double sA = -h0 / h1;            // h = 0
    const double sB = (length - h0) / h1;  // h = L
    const double bodyLo = std::min(sA, sB), bodyHi = std::max(sA, sB);
    addPiece(fPerp, gPerp, comp.radius, comp.strength, bodyLo, bodyHi, pieces);
    if (h1 > 0) {
        addPiece(f, g, comp.radius, comp.strength, -kAll, sA, pieces);
        addPiece(f - w, g, comp.radius, comp.strength, sB, kAll, pieces);
    } else {
        addPiece(f, g, comp.radius, comp.strength, sA, kAll, pieces);
        addPiece(f - w, g, comp.radius, comp.strength, -kAll, sB, pieces);
    }
}

}  // namespace

double Blob::Component::field(const Vec3& p) const {
    const Vec3 q = transformed ? toBlob.inversePoint(p) : p;
    const Vec3 nearest = kind == Kind::Sphere ? a : nearestOnSegment(q, a, b);
    const Vec3 v = q - nearest;
    const double e = 1 - dot(v, v) / (radius * radius);
    return e > 0 ? strength * e * e : 0;
}

Vec3 Blob::Component::gradient(const Vec3& p) const {
    const Vec3 q = transformed ? toBlob.inversePoint(p) : p;
    const Vec3 nearest = kind == Kind::Sphere ? a : nearestOnSegment(q, a, b);
    const Vec3 v = q - nearest;
    const double r2 = radius * radius;
    const double e = 1 - dot(v, v) / r2;
    if (e <= 0) return {};
    const Vec3 local = v * (-4 * strength * e / r2);
    // A gradient maps by the inverse transpose, as a normal does.
    return transformed ? toBlob.normal(local) : local;
}

Bounds Blob::Component::bounds() const {
    const Vec3 r(radius, radius, radius);
    Bounds box{a - r, a + r};
    if (kind == Kind::Cylinder) box.extend(Bounds{b - r, b + r});
    return transformed ? box.transformed(toBlob) : box;
}

Blob::Blob(std::vector<Component> components, double threshold, bool sturm)
    : components_(std::move(components)), threshold_(threshold), sturm_(sturm) {
    // Only positive components can lift the field to a positive threshold.
    for (const Component& c : components_)
        if (c.strength > 0) bounds_.extend(c.bounds());
    if (threshold_ <= 0) bounds_ = Bounds::infinite();
}

Blob Blob::withSturm(bool sturm) const {
    Blob copy = *this;
    copy.sturm_ = sturm;
    return copy;
}

double Blob::density(const Vec3& p) const {
    double sum = 0;
    for (const Component& c : components_) sum += c.field(p);
    return sum;
}

Vec3 Blob::normal(const Vec3& p) const {
    Vec3 g;
    for (const Component& c : components_) g += c.gradient(p);
    // The field falls off outwards.
    const double len = length(g);
    return len > 0 ? g / -len : Vec3(0, 1, 0);
}

void Blob::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    if (bounds_.isEmpty()) return;
    const Vec3 centre = bounds_.isFinite() ? (bounds_.lo + bounds_.hi) * 0.5 : Vec3(0, 0, 0);
    const detail::RecentredRay rr(ray, centre);
    if (!rr.valid()) return;
    // Per-thread scratch: a blob is hit by every ray of its scenes, and two
    // fresh vectors per ray cost more than the pieces' arithmetic.
    ScratchVector<FieldPiece> pieceScratch;
    ScratchVector<double> cutScratch;
    std::vector<FieldPiece>& pieces = pieceScratch.get();
    for (const Component& c : components_) componentPieces(c, rr.base, rr.dir, pieces);
    if (pieces.empty()) return;
    const double sMin = rr.sOf(tMin), sMax = rr.sOf(tMax);
    // Cut the ray at every piece's ends; between two cuts the field is one
    // quartic, the sum of the pieces covering that span.
    std::vector<double>& cuts = cutScratch.get();
    for (const FieldPiece& p : pieces) {
        cuts.push_back(p.lo);
        cuts.push_back(p.hi);
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    const std::size_t first = ts.size();
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double lo = std::max(cuts[i], sMin), hi = std::min(cuts[i + 1], sMax);
        if (!(lo <= hi)) continue;
        double c[5] = {-threshold_, 0, 0, 0, 0};
        double ceiling = 0;  // no point of the span has a larger field
        bool any = false;
        for (const FieldPiece& p : pieces) {
            if (p.lo > cuts[i] || p.hi < cuts[i + 1]) continue;
            for (int k = 0; k < 5; ++k) c[k] += p.c[k];
            ceiling += std::max(p.peak, 0.0);
            any = true;
        }
        if (!any) continue;  // field 0 here: below any positive threshold
        // A span whose field cannot reach a positive threshold has no
        // surface: most spans of a ray grazing a few components.
        if (threshold_ > 0 && ceiling < threshold_) continue;
        double roots[4];
        const int n = realRootsInInterval(c, lo, hi, roots,
                                          sturm_ ? RootMethod::Sturm : RootMethod::ClosedForm);
        for (int k = 0; k < n; ++k) detail::keepIfInRange(rr.tOf(roots[k]), tMin, tMax, ts);
    }
    // A root on a cut is found on both sides of it.
    std::sort(ts.begin() + static_cast<std::ptrdiff_t>(first), ts.end());
    const auto last = std::unique(
        ts.begin() + static_cast<std::ptrdiff_t>(first), ts.end(),
        [](double a, double b) { return b - a <= 1e-12 * std::max(std::fabs(a), std::fabs(b)); });
    ts.erase(last, ts.end());
}

}  // namespace frameray::scene
