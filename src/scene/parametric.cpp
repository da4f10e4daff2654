#include "scene/parametric.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "scene/implicit_search.h"
#include "scene/shape_math.h"

namespace frameray::scene {

Parametric::Parametric(ParametricSettings settings) : s_(std::move(settings)) {
    const Bounds b = bounds();
    scale_ = std::max(1e-300, length(b.hi - b.lo));
    buildTree();
    if (s_.precomputeDepth > 0) {
        for (int axis = 0; axis < 3; ++axis) {
            if (!s_.precomputeAxis[axis]) continue;
            precomputed_[axis].resize(std::size_t{1} << s_.precomputeDepth);
            precompute(axis, 1, s_.uMin, s_.uMax, s_.vMin, s_.vMax);
        }
    }
}

namespace {

// Bounds of a function along a stretch of length `width` whose ends take
// the values a and b, if it changes at most at rate `gradient`.
void boundStretch(double width, double a, double b, double gradient, double& lo, double& hi) {
    const double slack = std::max(0.0, 0.5 * (gradient * width - std::fabs(a - b)));
    lo = std::min(a, b) - slack;
    hi = std::max(a, b) + slack;
}

// The hits found last on this thread, with the (u, v) they were found
// with: the normal and uv_mapping need them, and a shape is only given
// the point. A small ring, so a few other parametric tests between the
// hit and its shading do not push it out.
struct RememberedHit {
    const void* shape = nullptr;
    Vec3 p;
    double u = 0, v = 0;
};
constexpr std::size_t kRemembered = 8;
struct RememberedHits {
    std::array<RememberedHit, kRemembered> hits;
    std::size_t next = 0;
};
RememberedHits& rememberedHits() {
    thread_local RememberedHits ring;
    return ring;
}

}  // namespace

Parametric::Range Parametric::coordinateRange(int axis, double u0, double u1, double v0,
                                              double v1) const {
    const CompiledFunction& f = axis == 0 ? *s_.fx : axis == 1 ? *s_.fy : *s_.fz;
    auto at = [&](double u, double v) {
        const double args[3] = {u, v, 0};
        // povray bounds the function minus the accuracy (measured: its hits
        // lie that much nearer along each axis).
        return f.eval(args) - s_.accuracy;
    };
    const double g = s_.maxGradient;
    double lowLo, lowHi, highLo, highHi;  // along the edges u = u0 and u = u1
    boundStretch(v1 - v0, at(u0, v0), at(u0, v1), g, lowLo, lowHi);
    boundStretch(v1 - v0, at(u1, v0), at(u1, v1), g, highLo, highHi);
    Range r{}, unused{};
    boundStretch(u1 - u0, lowHi, highHi, g, unused.lo, r.hi);
    boundStretch(u1 - u0, lowLo, highLo, g, r.lo, unused.hi);
    return r;
}

void Parametric::precompute(int axis, std::uint64_t number, double u0, double u1, double v0,
                            double v1) {
    std::vector<Range>& table = precomputed_[axis];
    if (number >= table.size() / 2) {  // the last level
        table[number] = coordinateRange(axis, u0, u1, v0, v1);
        return;
    }
    if (u1 - u0 < v1 - v0) {
        const double vm = 0.5 * (v0 + v1);
        precompute(axis, 2 * number, u0, u1, v0, vm);
        precompute(axis, 2 * number + 1, u0, u1, vm, v1);
    } else {
        const double um = 0.5 * (u0 + u1);
        precompute(axis, 2 * number, u0, um, v0, v1);
        precompute(axis, 2 * number + 1, um, u1, v0, v1);
    }
    const Range& a = table[2 * number];
    const Range& b = table[2 * number + 1];
    table[number] = {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}

bool Parametric::containerSpan(const Ray& ray, double& t0, double& t1) const {
    if (s_.sphereContainer) {
        // povray: no span when the ray starts outside and the centre lies
        // behind it, or when it only grazes the sphere.
        const Vec3 oc = s_.center - ray.origin;
        const double speed2 = dot(ray.direction, ray.direction);
        if (!(speed2 > 0)) return false;
        const double closest = dot(oc, ray.direction) / speed2;
        const double r2 = s_.radius * s_.radius;
        const double oc2 = dot(oc, oc);
        if (oc2 >= r2 && closest * std::sqrt(speed2) < 1e-10) return false;
        const double half2 = (r2 - oc2) / speed2 + closest * closest;
        if (!(half2 * speed2 > 1e-10)) return false;
        const double half = std::sqrt(half2);
        t0 = closest - half;
        t1 = closest + half;
        return true;
    }
    // A box: from the ray's start when it starts inside.
    if (!detail::clipToBox(ray, s_.boxLo, s_.boxHi, t0, t1)) return false;
    t0 = std::max(t0, 0.0);
    return t1 >= 1e-6;
}

void Parametric::buildTree() {
    tree_.push_back({rootSector(s_.maxGradient), -1, 0});
    tree_[0].sector.node = 0;
    // Breadth first, so children come after their parents.
    Sector kids[4];
    for (size_t i = 0; i < tree_.size(); ++i) {
        if (tree_[i].sector.depth >= kTreeDepth) continue;
        const int n = split(tree_[i].sector, s_.maxGradient, kids);
        tree_[i].firstChild = static_cast<int>(tree_.size());
        tree_[i].childCount = n;
        for (int k = 0; k < n; ++k) {
            kids[k].node = static_cast<int>(tree_.size());
            tree_.push_back({kids[k], -1, 0});
        }
    }
    // A node's box is the union of its children's: they bound the same
    // surface more tightly.
    for (size_t i = tree_.size(); i-- > 0;) {
        TreeNode& node = tree_[i];
        if (node.childCount == 0) continue;
        Vec3 lo(kInfinity), hi(-kInfinity);
        for (int k = 0; k < node.childCount; ++k) {
            lo = vmin(lo, tree_[node.firstChild + k].sector.lo);
            hi = vmax(hi, tree_[node.firstChild + k].sector.hi);
        }
        node.sector.lo = lo;
        node.sector.hi = hi;
    }
}

Bounds Parametric::bounds() const {
    if (s_.sphereContainer) return {s_.center - Vec3(s_.radius), s_.center + Vec3(s_.radius)};
    return {s_.boxLo, s_.boxHi};
}

void Parametric::derivatives(double u, double v, Vec3& pu, Vec3& pv) const {
    const double hu = 1e-6 * std::max(1.0, std::fabs(u));
    const double hv = 1e-6 * std::max(1.0, std::fabs(v));
    pu = (point(u + hu, v) - point(u - hu, v)) / (2 * hu);
    pv = (point(u, v + hv) - point(u, v - hv)) / (2 * hv);
}

// The bounding box of a sector's piece of surface: the box of its corners
// (and middle, in the first levels) grown by max_gradient times the
// distance from a corner to the middle. Sampling the surface (as povray
// does: a steep but straight surface needs no large max_gradient there)
// rather than trusting max_gradient alone keeps pieces whose gradient was
// underestimated; the middle keeps a large sector whose corners coincide
// (a whole period of a torus) from shrinking to a point.
void Parametric::sectorBox(const Sector& s, double gradient, Vec3& lo, Vec3& hi) const {
    lo = vmin(vmin(s.p[0], s.p[1]), vmin(s.p[2], s.p[3]));
    hi = vmax(vmax(s.p[0], s.p[1]), vmax(s.p[2], s.p[3]));
    if (s.depth <= kTreeDepth) {
        lo = vmin(lo, s.p[4]);
        hi = vmax(hi, s.p[4]);
    }
    const double hu = 0.5 * (s.u1 - s.u0), hv = 0.5 * (s.v1 - s.v0);
    const double r = gradient * std::sqrt(hu * hu + hv * hv) + 1e-12 * scale_;
    lo -= Vec3(r);
    hi += Vec3(r);
}

Parametric::Sector Parametric::rootSector(double gradient) const {
    if (!tree_.empty() && gradient == s_.maxGradient) return tree_[0].sector;
    Sector s{s_.uMin, s_.uMax, s_.vMin, s_.vMax, {}, 0, 0, {}, {}, -1};
    s.p[0] = point(s.u0, s.v0);
    s.p[1] = point(s.u1, s.v0);
    s.p[2] = point(s.u0, s.v1);
    s.p[3] = point(s.u1, s.v1);
    s.p[4] = point(0.5 * (s.u0 + s.u1), 0.5 * (s.v0 + s.v1));
    sectorBox(s, gradient, s.lo, s.hi);
    return s;
}

int Parametric::split(const Sector& s, double gradient, Sector* kids) const {
    if (s.node >= 0 && gradient == s_.maxGradient && tree_[s.node].firstChild >= 0) {
        const TreeNode& node = tree_[s.node];
        for (int k = 0; k < node.childCount; ++k) kids[k] = tree_[node.firstChild + k].sector;
        return node.childCount;
    }
    const double acc = s_.accuracy;
    const bool splitU = s.u1 - s.u0 > acc, splitV = s.v1 - s.v0 > acc;
    if ((!splitU && !splitV) || s.depth >= kMaxDepth) return 0;
    const double um = 0.5 * (s.u0 + s.u1), vm = 0.5 * (s.v0 + s.v1);
    // The 3x3 grid of points over the sector (only the rows and columns
    // that are split are new).
    Vec3 g[3][3];  // g[i][j] at (u_i, v_j), i, j in {0, middle, 1}
    g[0][0] = s.p[0];
    g[2][0] = s.p[1];
    g[0][2] = s.p[2];
    g[2][2] = s.p[3];
    if (splitU) {
        g[1][0] = point(um, s.v0);
        g[1][2] = point(um, s.v1);
    }
    if (splitV) {
        g[0][1] = point(s.u0, vm);
        g[2][1] = point(s.u1, vm);
    }
    if (splitU && splitV) g[1][1] = s.depth <= kTreeDepth ? s.p[4] : point(um, vm);
    const int iu[2][2] = {{0, splitU ? 1 : 2}, {splitU ? 1 : 0, 2}};
    const int iv[2][2] = {{0, splitV ? 1 : 2}, {splitV ? 1 : 0, 2}};
    int n = 0;
    for (int a = 0; a < (splitU ? 2 : 1); ++a) {
        for (int b = 0; b < (splitV ? 2 : 1); ++b) {
            Sector k{s.u0, s.u1, s.v0, s.v1, {}, s.depth + 1, 0, {}, {}, -1};
            if (splitU) (a == 0 ? k.u1 : k.u0) = um;
            if (splitV) (b == 0 ? k.v1 : k.v0) = vm;
            k.p[0] = g[iu[a][0]][iv[b][0]];
            k.p[1] = g[iu[a][1]][iv[b][0]];
            k.p[2] = g[iu[a][0]][iv[b][1]];
            k.p[3] = g[iu[a][1]][iv[b][1]];
            if (k.depth <= kTreeDepth) k.p[4] = point(0.5 * (k.u0 + k.u1), 0.5 * (k.v0 + k.v1));
            sectorBox(k, gradient, k.lo, k.hi);
            kids[n++] = k;
        }
    }
    return n;
}

void Parametric::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    // povray reports one crossing per ray, the first (see the header).
    double t;
    if (firstHit(ray, tMin, tMax, t)) ts.push_back(t);
}

bool Parametric::firstHit(const Ray& ray, double tMin, double tMax, double& tHit) const {
    double near, far;
    if (!containerSpan(ray, near, far)) return false;
    // A ray continuing from an earlier hit starts where that one was, as
    // povray's new ray from that point would.
    near = std::max(near, tMin);
    if (near == far) near = 0;
    near += 4 * s_.accuracy;
    if (near > far) return false;

    struct Piece {
        double u0, u1, v0, v1;
        std::uint64_t number;  // 1 for the whole rectangle, 2n and 2n + 1 for n's halves
    };
    constexpr int kStack = 64;
    constexpr std::uint64_t kLastNumber = 10000000;  // numbers past the tables stop growing
    Piece stack[kStack];
    int top = 0;
    stack[0] = {s_.uMin, s_.uMax, s_.vMin, s_.vMax, 1};
    double best = kInfinity, bestU = 0, bestV = 0;
    double entry = 0;  // where the ray enters the piece's last slab
    while (top >= 0) {
        const Piece piece = stack[top];
        const double du = piece.u1 - piece.u0, dv = piece.v1 - piece.v0;
        const bool alongV = dv > du;
        double size = alongV ? dv : du;
        double slabIn[3], slabOut[3];
        bool crossed[3] = {false, false, false};
        double stretch = 0;  // the longest stretch of the ray through one slab
        bool dropped = false;
        for (int a = 0; a < 3 && !dropped; ++a) {
            const std::vector<Range>& table = precomputed_[a];
            const Range r = piece.number < table.size()
                                ? table[piece.number]
                                : coordinateRange(a, piece.u0, piece.u1, piece.v0, piece.v1);
            const double o = ray.origin[a], d = ray.direction[a];
            if (std::fabs(d) < 1e-10) {
                dropped = r.hi < o || r.lo > o;
                continue;
            }
            double tIn = (r.hi - o) / d, tOut = (r.lo - o) / d;
            if (tIn > tOut) std::swap(tIn, tOut);
            if (tIn > far || tOut < near) {
                dropped = true;
                break;
            }
            entry = tIn;
            if (entry > best) {
                dropped = true;
                break;
            }
            for (int b = 0; b < a; ++b)
                if (crossed[b] && (tIn > slabOut[b] || tOut < slabIn[b])) dropped = true;
            crossed[a] = true;
            slabIn[a] = tIn;
            slabOut[a] = tOut;
            stretch = std::max(stretch, tOut - tIn);
        }
        if (dropped) {
            --top;
            continue;
        }
        size = std::min(size, stretch);
        if (size < s_.accuracy || top + 1 >= kStack) {
            if (best > entry && entry > near) {
                best = entry;
                bestU = piece.u0;
                bestV = piece.v0;
            }
            --top;
            continue;
        }
        // Halve the longer side; the lower half is searched first.
        const std::uint64_t number = std::min(2 * piece.number, kLastNumber);
        Piece lower = piece, upper = piece;
        if (alongV) {
            lower.v1 = upper.v0 = 0.5 * (piece.v0 + piece.v1);
        } else {
            lower.u1 = upper.u0 = 0.5 * (piece.u0 + piece.u1);
        }
        lower.number = number;
        upper.number = number + 1;
        stack[top] = upper;
        stack[++top] = lower;
    }
    if (!(best < far) || !(best > tMin) || !(best < tMax)) return false;
    tHit = best;
    RememberedHits& ring = rememberedHits();
    ring.hits[ring.next] = {this, ray.at(best), bestU, bestV};
    ring.next = (ring.next + 1) % kRemembered;
    return true;
}

bool Parametric::rememberedUv(const Vec3& p, double& u, double& v) const {
    const RememberedHits& ring = rememberedHits();
    const double tolerance = 1e-9 * scale_;
    for (std::size_t k = 0; k < kRemembered; ++k) {
        // Newest first: a point met twice keeps its latest (u, v).
        const RememberedHit& h = ring.hits[(ring.next + kRemembered - 1 - k) % kRemembered];
        if (h.shape != this) continue;
        const Vec3 d = h.p - p;
        if (std::fabs(d.x) <= tolerance && std::fabs(d.y) <= tolerance &&
            std::fabs(d.z) <= tolerance) {
            u = h.u;
            v = h.v;
            return true;
        }
    }
    return false;
}

bool Parametric::uv(const Vec3& p, double& u, double& v) const {
    if (rememberedUv(p, u, v)) return true;
    u = 0.5 * (s_.uMin + s_.uMax);
    v = 0.5 * (s_.vMin + s_.vMax);
    parametersOf(p, u, v);
    return true;
}

Vec3 Parametric::normalAtParameters(double u, double v) const {
    const Vec3 at = point(u, v);
    const Vec3 n = cross(point(u + s_.accuracy, v) - at, point(u, v + s_.accuracy) - at);
    const double len = length(n);
    if (!(len > 0) || !std::isfinite(len)) return Vec3(0, 1, 0);
    return n / len;
}

bool Parametric::parametersOf(const Vec3& p, double& u, double& v) const {
    // A max_gradient too small for the surface can hide the piece the
    // point lies on (povray still finds hits there): search again with
    // larger ones.
    double bestResidual = kInfinity;
    double gradient = s_.maxGradient;
    for (int attempt = 0; attempt < 4; ++attempt, gradient *= 8)
        if (parametersOf(p, gradient, u, v, bestResidual)) return true;
    return bestResidual < kInfinity;
}

bool Parametric::parametersOf(const Vec3& p, double gradient, double& uOut, double& vOut,
                              double& bestResidual) const {
    // Gauss-Newton on |point(u, v) - p| from the middle of a leaf sector.
    auto settle = [&](const Sector& s) {
        double u = 0.5 * (s.u0 + s.u1), v = 0.5 * (s.v0 + s.v1);
        for (int i = 0; i < 16; ++i) {
            const Vec3 f = point(u, v) - p;
            Vec3 pu, pv;
            derivatives(u, v, pu, pv);
            const double a = dot(pu, pu), b = dot(pu, pv), c = dot(pv, pv);
            const double det = a * c - b * b;
            if (!(det > 0)) break;
            const double gu = dot(pu, f), gv = dot(pv, f);
            const double stepU = -(c * gu - b * gv) / det;
            const double stepV = -(a * gv - b * gu) / det;
            u = std::clamp(u + stepU, s_.uMin, s_.uMax);
            v = std::clamp(v + stepV, s_.vMin, s_.vMax);
            if (std::fabs(stepU) + std::fabs(stepV) <= 1e-14 * (1 + std::fabs(u) + std::fabs(v)))
                break;
        }
        const double residual = length(point(u, v) - p);
        if (residual < bestResidual) {
            bestResidual = residual;
            uOut = u;
            vOut = v;
        }
        return residual <= 1e-8 * scale_;
    };
    auto contains = [&](const Sector& s) {
        const Vec3 m(1e-7 * scale_);
        const Vec3 bl = s.lo - m, bh = s.hi + m;
        return p.x >= bl.x && p.x <= bh.x && p.y >= bl.y && p.y <= bh.y && p.z >= bl.z &&
               p.z <= bh.z;
    };

    std::vector<Sector> stack;
    stack.reserve(64);
    stack.push_back(rootSector(gradient));
    Sector kids[4];
    while (!stack.empty()) {
        const Sector s = stack.back();
        stack.pop_back();
        const int count = split(s, gradient, kids);
        if (count == 0) {
            if (settle(s)) return true;
            continue;
        }
        for (int i = 0; i < count; ++i)
            if (contains(kids[i])) stack.push_back(kids[i]);
    }
    return false;
}

Vec3 Parametric::normal(const Vec3& p) const {
    double u, v;
    if (rememberedUv(p, u, v)) return normalAtParameters(u, v);
    // A point this thread did not find: the nearest surface point's normal.
    u = 0.5 * (s_.uMin + s_.uMax);
    v = 0.5 * (s_.vMin + s_.vMax);
    parametersOf(p, u, v);
    Vec3 pu, pv;
    derivatives(u, v, pu, pv);
    Vec3 n = cross(pu, pv);
    // Where the surface pinches to a point (a sphere's pole) the
    // derivatives are parallel: take the normal a little way inside the
    // rectangle instead.
    if (!(length(n) > 1e-9 * length(pu) * length(pv)) || !(length(n) > 0)) {
        const double du = 1e-5 * (s_.uMax - s_.uMin), dv = 1e-5 * (s_.vMax - s_.vMin);
        const double u2 = u + du <= s_.uMax ? u + du : u - du;
        const double v2 = v + dv <= s_.vMax ? v + dv : v - dv;
        derivatives(u2, v2, pu, pv);
        n = cross(pu, pv);
    }
    const double len = length(n);
    if (!(len > 0) || !std::isfinite(len)) return Vec3(0, 1, 0);
    return n / len;
}

}  // namespace frameray::scene
