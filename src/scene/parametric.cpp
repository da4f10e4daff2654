#include "scene/parametric.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "scene/implicit_search.h"
#include "scene/shape_math.h"

namespace frameray::scene {

namespace {

bool inRange(double x, double lo, double hi, double margin) {
    return x >= lo - margin && x <= hi + margin;
}

}  // namespace

Parametric::Parametric(ParametricSettings settings) : s_(std::move(settings)) {
    const Bounds b = bounds();
    scale_ = std::max(1e-300, length(b.hi - b.lo));
    buildTree();
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

bool Parametric::containerInterval(const Ray& ray, double& t0, double& t1) const {
    if (s_.sphereContainer)
        return detail::distanceRoots(ray.origin - s_.center, ray.direction, s_.radius * s_.radius,
                                     t0, t1);
    return detail::clipToBox(ray, s_.boxLo, s_.boxHi, t0, t1);
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
    double c0, c1;
    if (!containerInterval(ray, c0, c1)) return false;
    const double speed = length(ray.direction);
    if (!(speed > 0)) return false;
    // A ray leaving the surface (shadows, reflections) must not find its
    // own start again.
    const double lo = std::max(c0, tMin + 1e-9 * scale_ / speed);
    double best = std::min(c1, tMax);
    if (!(lo < best)) return false;

    // The ray's entry into the box of a sector, within [lo, best].
    auto enters = [&](const Sector& s, double& near) {
        const Vec3& bl = s.lo;
        const Vec3& bh = s.hi;
        near = lo;
        double far = best;
        for (int a = 0; a < 3; ++a) {
            const double o = ray.origin[a], d = ray.direction[a];
            if (d == 0) {
                if (o < bl[a] || o > bh[a]) return false;
                continue;
            }
            double ta = (bl[a] - o) / d, tb = (bh[a] - o) / d;
            if (ta > tb) std::swap(ta, tb);
            near = std::max(near, ta);
            far = std::min(far, tb);
            if (near > far) return false;
        }
        return true;
    };

    // Newton's method on point(u, v) = origin + t direction, from the
    // middle of a leaf sector; the root counts when it lies in (or next
    // to) that sector, inside the rectangle, and nearer than `best`.
    auto solve = [&](const Sector& s) {
        const double du = s.u1 - s.u0, dv = s.v1 - s.v0;
        double u = s.u0 + 0.5 * du, v = s.v0 + 0.5 * dv;
        const Vec3 c = point(u, v);
        double t = dot(c - ray.origin, ray.direction) / (speed * speed);
        bool converged = false;
        for (int i = 0; i < 24; ++i) {
            const Vec3 f = point(u, v) - ray.at(t);
            Vec3 pu, pv;
            derivatives(u, v, pu, pv);
            const Vec3 nd = -ray.direction;
            const Vec3 bxc = cross(pv, nd);
            const double det = dot(pu, bxc);
            if (!(std::fabs(det) > 0) || !std::isfinite(det)) return false;
            const double stepU = -dot(f, bxc) / det;
            const double stepV = -dot(pu, cross(f, nd)) / det;
            const double stepT = -dot(pu, cross(pv, f)) / det;
            u += stepU;
            v += stepV;
            t += stepT;
            if (!std::isfinite(u + v + t)) return false;
            // Far outside its sector: the root (if any) belongs to another.
            if (!inRange(u, s.u0, s.u1, 4 * du + 1e-9) || !inRange(v, s.v0, s.v1, 4 * dv + 1e-9))
                return false;
            if (std::fabs(stepU) <= 1e-13 * std::max(1.0, std::fabs(u)) &&
                std::fabs(stepV) <= 1e-13 * std::max(1.0, std::fabs(v))) {
                converged = true;
                break;
            }
        }
        const double residual = length(point(u, v) - ray.at(t));
        if (!converged && !(residual <= 1e-10 * scale_)) return false;
        if (!(residual <= 1e-7 * scale_)) return false;
        const double eu = 1e-9 * std::max(1.0, std::fabs(s_.uMax - s_.uMin));
        const double ev = 1e-9 * std::max(1.0, std::fabs(s_.vMax - s_.vMin));
        if (!inRange(u, s.u0, s.u1, du + eu) || !inRange(v, s.v0, s.v1, dv + ev)) return false;
        if (!inRange(u, s_.uMin, s_.uMax, eu) || !inRange(v, s_.vMin, s_.vMax, ev)) return false;
        if (!(t > lo && t < best)) return false;
        best = t;
        return true;
    };

    std::vector<Sector> stack;
    stack.reserve(64);
    bool found = false;
    {
        Sector root = rootSector(s_.maxGradient);
        if (!enters(root, root.tNear)) return false;
        stack.push_back(root);
    }
    Sector kids[4];
    while (!stack.empty()) {
        const Sector s = stack.back();
        stack.pop_back();
        if (s.tNear >= best) continue;
        const int count = split(s, s_.maxGradient, kids);
        if (count == 0) {
            if (solve(s)) found = true;
            continue;
        }
        // The children whose boxes the ray crosses, nearest popped first.
        int n = 0;
        for (int i = 0; i < count; ++i)
            if (enters(kids[i], kids[i].tNear)) kids[n++] = kids[i];
        for (int i = 1; i < n; ++i)
            for (int j = i; j > 0 && kids[j - 1].tNear < kids[j].tNear; --j)
                std::swap(kids[j - 1], kids[j]);
        for (int i = 0; i < n; ++i) stack.push_back(kids[i]);
    }
    if (found) tHit = best;
    return found;
}

bool Parametric::parametersOf(const Vec3& p, double& u, double& v) const {
    // A max_gradient too small for the surface can hide the piece the
    // point lies on (povray still finds hits there): search again with
    // larger ones.
    double bestResidual = kInfinity;
    for (double gradient = s_.maxGradient, i = 0; i < 4; gradient *= 8, ++i)
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
    double u = 0.5 * (s_.uMin + s_.uMax), v = 0.5 * (s_.vMin + s_.vMax);
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
