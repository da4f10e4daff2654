#include "scene/prism.h"

#include <algorithm>
#include <cmath>

#include "scene/shape_math.h"

namespace frameray::scene {

namespace {

bool samePoint(const ProfilePoint& a, const ProfilePoint& b) {
    return a.u == b.u && a.v == b.v;
}

double poly3(const double c[4], double s) {
    return ((c[3] * s + c[2]) * s + c[1]) * s + c[0];
}

}  // namespace

std::vector<ProfileSegment> Prism::outlineOf(SplineKind kind, const std::vector<ProfilePoint>& p,
                                             bool& unclosed) {
    std::vector<ProfileSegment> out;
    const size_t n = p.size();
    unclosed = false;
    // The first point on the curve of the current sub-shape, and the piece
    // layout: piece i uses points i .. i + per - 1 and ends at point
    // i + endOffset.
    const size_t per = static_cast<size_t>(pointsPerSegment(kind));
    const size_t firstOnCurve = kind == SplineKind::Quadratic || kind == SplineKind::Cubic ? 1 : 0;
    const size_t endOffset = kind == SplineKind::Linear ? 1 : (kind == SplineKind::Bezier ? 3 : 2);
    size_t start = 0;
    size_t i = 0;
    while (i + per <= n) {
        out.push_back(makeProfileSegment(kind, &p[i]));
        if (samePoint(p[i + endOffset], p[start + firstOnCurve])) {
            // Closed: the next sub-shape starts after this one's points.
            start = i + per;
            i = start;
        } else {
            i += kind == SplineKind::Bezier ? 4 : 1;
        }
    }
    if (start < n) {
        unclosed = true;
        if (kind == SplineKind::Linear && n - start >= 2) {
            const ProfilePoint closing[2] = {p[n - 1], p[start]};
            out.push_back(makeProfileSegment(SplineKind::Linear, closing));
        }
    }
    return out;
}

Prism::Prism(std::vector<ProfileSegment> outline, double h1, double h2, bool conic, bool open)
    : outline_(std::move(outline)),
      h1_(std::min(h1, h2)),
      h2_(std::max(h1, h2)),
      conic_(conic),
      open_(open) {
    double uMin = kInfinity, uMax = -kInfinity, vMin = kInfinity, vMax = -kInfinity;
    for (const auto& s : outline_) {
        uMin = std::min(uMin, s.uMin);
        uMax = std::max(uMax, s.uMax);
        vMin = std::min(vMin, s.vMin);
        vMax = std::max(vMax, s.vMax);
    }
    if (!conic_) {
        bounds_ = {{uMin, h1_, vMin}, {uMax, h2_, vMax}};
    } else {
        // The outline scaled by y is extreme at one of the two heights.
        for (const double h : {h1_, h2_}) {
            bounds_.extend(Vec3(uMin * h, h, vMin * h));
            bounds_.extend(Vec3(uMax * h, h, vMax * h));
        }
    }
}

bool Prism::insideOutline(double x, double z) const {
    int crossings = 0;
    for (const ProfileSegment& seg : outline_) {
        if (z < seg.vMin || z > seg.vMax || x > seg.uMax) continue;
        double g[4] = {seg.v[0] - z, seg.v[1], seg.v[2], seg.v[3]};
        double roots[3];
        const int n = cubicRootsIn(g, 0, 1, roots);
        for (int i = 0; i < n; ++i)
            if (roots[i] < 1 && poly3(seg.u, roots[i]) > x) ++crossings;
    }
    return crossings % 2 == 1;
}

double Prism::closestPiece(double x, double z, const ProfileSegment*& best, double& bestS) const {
    double bestD = kInfinity;
    best = nullptr;
    for (const ProfileSegment& seg : outline_) {
        // A piece whose box is farther than the best so far cannot be nearer.
        const double dx = std::max({seg.uMin - x, x - seg.uMax, 0.0});
        const double dz = std::max({seg.vMin - z, z - seg.vMax, 0.0});
        if (dx * dx + dz * dz > bestD) continue;
        double s;
        const double d = closestOnSegment(seg, x, z, s);
        if (d < bestD) {
            bestD = d;
            best = &seg;
            bestS = s;
        }
    }
    return bestD;
}

void Prism::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    const Vec3& o = ray.origin;
    const Vec3& d = ray.direction;
    std::vector<double> found;
    double roots[3];
    if (!conic_) {
        const double a = d.x * d.x + d.z * d.z;
        if (a > 0) {
            // Where the outline meets the vertical plane of the ray.
            for (const ProfileSegment& seg : outline_) {
                double c[4];
                for (int k = 0; k < 4; ++k) c[k] = -d.z * seg.u[k] + d.x * seg.v[k];
                c[0] -= -d.z * o.x + d.x * o.z;
                const int n = cubicRootsIn(c, 0, 1, roots);
                for (int i = 0; i < n; ++i) {
                    const ProfilePoint q = seg.at(roots[i]);
                    const double t = ((q.u - o.x) * d.x + (q.v - o.z) * d.z) / a;
                    const double y = o.y + t * d.y;
                    if (y >= h1_ && y <= h2_) found.push_back(t);
                }
            }
        }
        if (!open_ && d.y != 0) {
            for (const double h : {h1_, h2_}) {
                const double t = (h - o.y) / d.y;
                if (insideOutline(o.x + t * d.x, o.z + t * d.z)) found.push_back(t);
            }
        }
    } else {
        // The plane through the apex (the origin) and the ray meets the
        // outline at y = 1 where N . (u, 1, v) = 0.
        const Vec3 nrm = cross(o, d);
        if (dot(nrm, nrm) > 0) {
            for (const ProfileSegment& seg : outline_) {
                double c[4];
                for (int k = 0; k < 4; ++k) c[k] = nrm.x * seg.u[k] + nrm.z * seg.v[k];
                c[0] += nrm.y;
                const int n = cubicRootsIn(c, 0, 1, roots);
                for (int i = 0; i < n; ++i) {
                    const ProfilePoint q2 = seg.at(roots[i]);
                    const Vec3 q{q2.u, 1, q2.v};
                    // The ray point on the line through the origin and q.
                    const Vec3 dq = cross(d, q);
                    const double den = dot(dq, dq);
                    if (den == 0) continue;
                    const double t = -dot(cross(o, q), dq) / den;
                    const double y = o.y + t * d.y;
                    if (y >= h1_ && y <= h2_) found.push_back(t);
                }
            }
        }
        if (!open_ && d.y != 0) {
            for (const double h : {h1_, h2_}) {
                if (h == 0) continue;
                const double t = (h - o.y) / d.y;
                if (insideOutline((o.x + t * d.x) / h, (o.z + t * d.z) / h)) found.push_back(t);
            }
        }
    }
    detail::appendDistinctHits(found, tMin, tMax, ts);
}

Vec3 Prism::normal(const Vec3& p) const {
    const double scale = conic_ ? p.y : 1.0;
    const double x = scale != 0 ? p.x / scale : p.x, z = scale != 0 ? p.z / scale : p.z;
    const ProfileSegment* seg;
    double s = 0;
    const double d2 = closestPiece(x, z, seg, s);
    const double sideDistance = std::sqrt(d2) * std::fabs(scale);
    if (!open_) {
        if (std::fabs(p.y - h1_) < sideDistance) return {0, -1, 0};
        if (std::fabs(p.y - h2_) < sideDistance) return {0, 1, 0};
    }
    if (!seg) return {0, 1, 0};
    ProfilePoint tan = seg->tangent(s);
    if (tan.u == 0 && tan.v == 0) tan = seg->tangent(s < 0.5 ? s + 1e-6 : s - 1e-6);
    Vec3 n;
    if (!conic_) {
        n = Vec3(tan.v, 0, -tan.u);
    } else {
        const ProfilePoint q = seg->at(s);
        n = cross(Vec3(tan.u, 0, tan.v), Vec3(q.u, 1, q.v));
    }
    const double len = length(n);
    return len > 0 ? n / len : Vec3(0, 1, 0);
}

bool Prism::inside(const Vec3& p) const {
    if (p.y < h1_ || p.y > h2_) return false;
    if (!conic_) return insideOutline(p.x, p.z);
    if (p.y == 0) return false;
    return insideOutline(p.x / p.y, p.z / p.y);
}

}  // namespace frameray::scene
