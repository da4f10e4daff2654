#include "scene/spline_revolution.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

#include "scene/scratch.h"
#include "scene/shape_math.h"
#include "util/roots.h"

namespace frameray::scene {

namespace {

// A ray's distance from the y axis: rho^2(t) = a t^2 + 2 b t + c.
struct AxisDistance {
    double a, b, c;
    explicit AxisDistance(const Ray& r)
        : a(r.direction.x * r.direction.x + r.direction.z * r.direction.z),
          b(r.origin.x * r.direction.x + r.origin.z * r.direction.z),
          c(r.origin.x * r.origin.x + r.origin.z * r.origin.z) {}
    double at(double t) const { return (a * t + 2 * b) * t + c; }
    // The least value over [t0, t1].
    double minOver(double t0, double t1) const {
        if (a <= 0) return std::min(at(t0), at(t1));
        const double tc = std::clamp(-b / a, t0, t1);
        return at(tc);
    }
};

// The parameter interval where the ray's height lies in [lo, hi]; false
// when it never does.
bool heightInterval(const Ray& r, double lo, double hi, double& t0, double& t1) {
    const double py = r.origin.y, dy = r.direction.y;
    if (dy == 0) {
        t0 = -kInfinity;
        t1 = kInfinity;
        return py >= lo && py <= hi;
    }
    t0 = (lo - py) / dy;
    t1 = (hi - py) / dy;
    if (t0 > t1) std::swap(t0, t1);
    return true;
}

// Product of polynomials in increasing powers.
void multiply(const double* p, int np, const double* q, int nq, double* out) {
    std::fill(out, out + np + nq - 1, 0.0);
    // Zero top coefficients add only exact zeros to out (x + 0 == x, and
    // +0 + -0 == +0): skipping them gives the same bits.
    while (np > 1 && p[np - 1] == 0) --np;
    while (nq > 1 && q[nq - 1] == 0) --nq;
    for (int i = 0; i < np; ++i)
        for (int j = 0; j < nq; ++j) out[i + j] += p[i] * q[j];
}

// Squared distance from (u, v) to a piece's (u, v) box, widened by far more
// than rounding: a lower bound of closestOnSegment's distance, whose
// candidates all lie on the piece.
double boxDistance2(const ProfileSegment& seg, double u, double v) {
    const double padU = 1e-9 * (1 + std::fabs(seg.uMin) + std::fabs(seg.uMax)),
                 padV = 1e-9 * (1 + std::fabs(seg.vMin) + std::fabs(seg.vMax));
    const double du = std::max({seg.uMin - padU - u, 0.0, u - seg.uMax - padU}),
                 dv = std::max({seg.vMin - padV - v, 0.0, v - seg.vMax - padV});
    return du * du + dv * dv;
}

// The piece (index) and its parameter s nearest (u, v) by
// closestOnSegment, the first in order among equally near ones. Pieces
// whose box lies farther than the nearest found so far are skipped; the
// piece with the nearest box is measured first.
int closestPiece(const std::vector<ProfileSegment>& segments, double u, double v, double& s) {
    int first = -1;
    double firstBox = kInfinity;
    for (size_t i = 0; i < segments.size(); ++i) {
        const double b = boxDistance2(segments[i], u, v);
        if (b < firstBox) firstBox = b, first = static_cast<int>(i);
    }
    if (first < 0) return -1;
    double best = closestOnSegment(segments[static_cast<size_t>(first)], u, v, s);
    int bestIndex = first;
    for (size_t i = 0; i < segments.size(); ++i) {
        if (static_cast<int>(i) == first || boxDistance2(segments[i], u, v) > best) continue;
        double si;
        const double d = closestOnSegment(segments[i], u, v, si);
        if (d < best || (d == best && static_cast<int>(i) < bestIndex)) {
            best = d;
            s = si;
            bestIndex = static_cast<int>(i);
        }
    }
    return bestIndex;
}

double poly3(const double c[4], double s) {
    return ((c[3] * s + c[2]) * s + c[1]) * s + c[0];
}
double slope3(const double c[4], double s) {
    return (3 * c[3] * s + 2 * c[2]) * s + c[1];
}

}  // namespace

// --- Lathe --------------------------------------------------------------------

Lathe::Lathe(SplineKind kind, const std::vector<ProfilePoint>& points) {
    const int per = pointsPerSegment(kind);
    const int stride = kind == SplineKind::Bezier ? 4 : 1;
    for (size_t i = 0; i + static_cast<size_t>(per) <= points.size();
         i += static_cast<size_t>(stride))
        segments_.push_back(makeProfileSegment(kind, &points[i]));
    double rMax = 0, yMin = kInfinity, yMax = -kInfinity;
    for (const auto& s : segments_) {
        rMax = std::max({rMax, std::fabs(s.uMin), std::fabs(s.uMax)});
        yMin = std::min(yMin, s.vMin);
        yMax = std::max(yMax, s.vMax);
    }
    bounds_ = {{-rMax, yMin, -rMax}, {rMax, yMax, rMax}};
}

void Lathe::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    const AxisDistance rho(ray);
    const double py = ray.origin.y;
    const double dy = ray.direction.y;
    // Nearly horizontal rays are solved as horizontal (the height then
    // fixes the profile parameter) and refined below: the general
    // equation loses its precision as dy -> 0.
    const bool horizontal = std::fabs(dy) < 1e-7 * length(ray.direction);
    ScratchVector<double> scratch;
    std::vector<double>& found = scratch.get();
    for (const ProfileSegment& seg : segments_) {
        double t0, t1;
        if (!heightInterval(ray, seg.vMin, seg.vMax, t0, t1)) continue;
        t0 = std::max(t0, tMin);
        t1 = std::min(t1, tMax);
        if (horizontal) {
            t0 = tMin;
            t1 = tMax;
        }
        if (t0 > t1) continue;
        const double reach = std::max(std::fabs(seg.uMin), std::fabs(seg.uMax));
        if (rho.minOver(t0, t1) > reach * reach * (1 + 1e-9)) continue;

        double g[4];  // h(s) - py
        std::copy(seg.v, seg.v + 4, g);
        g[0] -= py;
        // Candidate (s, t) pairs, refined together below.
        double pairs[12][2];
        int nPairs = 0;
        if (rho.a == 0) {
            // Parallel to the axis: the profile's radius must equal the
            // ray's distance from the axis (cubic in s, exact even on it).
            const double dist = std::sqrt(rho.c);
            for (const double sign : {1.0, -1.0}) {
                if (dist == 0 && sign < 0) break;
                const double c[4] = {seg.u[0] - sign * dist, seg.u[1], seg.u[2], seg.u[3]};
                double sRoots[3];
                const int n = cubicRootsIn(c, 0, 1, sRoots);
                for (int i = 0; i < n; ++i) found.push_back((poly3(seg.v, sRoots[i]) - py) / dy);
            }
            continue;
        }
        if (horizontal) {
            double sRoots[3];
            const int n = cubicRootsIn(g, 0, 1, sRoots);
            for (int i = 0; i < n; ++i) {
                const double r = poly3(seg.u, sRoots[i]);
                double tq[2];
                const int m = solveQuadratic(rho.c - r * r, 2 * rho.b, rho.a, tq);
                for (int j = 0; j < m; ++j) {
                    pairs[nPairs][0] = sRoots[i];
                    pairs[nPairs++][1] = tq[j];
                }
            }
        } else {
            // a g^2 + 2 b dy g + dy^2 (c - r^2) = 0, degree 6 in s.
            double g2[7], r2[7], poly[7];
            multiply(g, 4, g, 4, g2);
            multiply(seg.u, 4, seg.u, 4, r2);
            for (int k = 0; k < 7; ++k) {
                poly[k] = rho.a * g2[k] - dy * dy * r2[k];
                if (k < 4) poly[k] += 2 * rho.b * dy * g[k];
            }
            poly[0] += dy * dy * rho.c;
            int degree = 6;
            while (degree > 0 && poly[degree] == 0) --degree;
            if (degree == 0) continue;
            double sRoots[6];
            const int n = realRootsInInterval(
                std::span<const double>(poly, static_cast<size_t>(degree) + 1), 0, 1, sRoots);
            for (int i = 0; i < n; ++i) {
                pairs[nPairs][0] = sRoots[i];
                pairs[nPairs++][1] = poly3(g, sRoots[i]) / dy;
            }
        }
        for (int i = 0; i < nPairs; ++i) {
            double s = pairs[i][0], t = pairs[i][1];
            // Newton steps on  py + t dy - h(s) = 0,  rho^2(t) - r(s)^2 = 0.
            for (int it = 0; it < 3; ++it) {
                const double h = poly3(seg.v, s), r = poly3(seg.u, s);
                const double f1 = py + t * dy - h, f2 = rho.at(t) - r * r;
                const double j11 = -slope3(seg.v, s), j12 = dy;
                const double j21 = -2 * r * slope3(seg.u, s), j22 = 2 * (rho.a * t + rho.b);
                const double det = j11 * j22 - j12 * j21;
                if (det == 0 || !std::isfinite(det)) break;
                const double ds = (f1 * j22 - f2 * j12) / det, dt = (j11 * f2 - j21 * f1) / det;
                if (!std::isfinite(ds) || !std::isfinite(dt) || std::fabs(ds) > 1e-3) break;
                s -= ds;
                t -= dt;
            }
            if (s < -1e-9 || s > 1 + 1e-9) continue;
            found.push_back(t);
        }
    }
    detail::appendDistinctHits(found, tMin, tMax, ts);
}

Vec3 Lathe::normal(const Vec3& p) const {
    const double rho = std::sqrt(p.x * p.x + p.z * p.z);
    double bestS = 0;
    const int index = closestPiece(segments_, rho, p.y, bestS);
    if (index < 0) return {0, 1, 0};
    const ProfileSegment* bestSeg = &segments_[static_cast<size_t>(index)];
    ProfilePoint tan = bestSeg->tangent(bestS);
    if (tan.u == 0 && tan.v == 0)  // a repeated control point: look just inside the piece
        tan = bestSeg->tangent(bestS < 0.5 ? bestS + 1e-6 : bestS - 1e-6);
    // Perpendicular to the profile in the (radius, height) plane.
    const double nu = tan.v, nv = -tan.u;
    if (rho == 0) return {0, nv >= 0 ? 1.0 : -1.0, 0};
    const Vec3 n{nu * p.x / rho, nv, nu * p.z / rho};
    const double len = length(n);
    return len > 0 ? n / len : Vec3(0, 1, 0);
}

namespace {

// The turns around y from +x towards +z (lathe and sor uv, as the sphere's).
double turnsAroundY(const Vec3& p) {
    double angle = std::atan2(p.z, p.x) / (2 * std::numbers::pi);
    return angle < 0 ? angle + 1 : angle;
}

}  // namespace

// povray 3.7's lathe uv (measured): u around the axis as a sphere's, v
// through the profile's pieces, each an equal share whatever its height,
// by the piece's own parameter.
bool Lathe::uv(const Vec3& p, double& u, double& v) const {
    const double rho = std::sqrt(p.x * p.x + p.z * p.z);
    double bestS = 0;
    const std::size_t bestIndex =
        static_cast<std::size_t>(std::max(closestPiece(segments_, rho, p.y, bestS), 0));
    u = turnsAroundY(p);
    v = segments_.empty() ? 0 : (static_cast<double>(bestIndex) + bestS) / segments_.size();
    return true;
}

bool Lathe::inside(const Vec3& p) const {
    // Crossings of the profile by the line from (rho, y) outwards.
    const double rho = std::sqrt(p.x * p.x + p.z * p.z);
    int crossings = 0;
    for (const ProfileSegment& seg : segments_) {
        if (p.y < seg.vMin || p.y > seg.vMax) continue;
        double g[4];
        std::copy(seg.v, seg.v + 4, g);
        g[0] -= p.y;
        double roots[3];
        const int n = cubicRootsIn(g, 0, 1, roots);
        for (int i = 0; i < n; ++i)
            if (roots[i] < 1 && poly3(seg.u, roots[i]) > rho) ++crossings;
    }
    return crossings % 2 == 1;
}

// --- Sor ----------------------------------------------------------------------

Sor::Sor(const std::vector<ProfilePoint>& pts, bool open) : open_(open) {
    // Piece i runs from point i + 1 to point i + 2; r^2 is the cubic in h
    // through both with slopes taken from the neighbouring points.
    for (size_t i = 0; i + 3 < pts.size(); ++i) {
        const ProfilePoint &p0 = pts[i], &p1 = pts[i + 1], &p2 = pts[i + 2], &p3 = pts[i + 3];
        Piece piece;
        piece.h0 = p1.v;
        piece.h1 = p2.v;
        const double span = p2.v - p1.v;
        // d(r^2)/dh = 2 r dr/dh, dr/dh by the centred difference over the
        // neighbours (matches povray 3.7's sor exactly).
        const double m1 = 2 * p1.u * (p2.u - p0.u) / (p2.v - p0.v);
        const double m2 = 2 * p2.u * (p3.u - p1.u) / (p3.v - p1.v);
        const double q1 = p1.u * p1.u, q2 = p2.u * p2.u;
        piece.c[0] = q1;
        piece.c[1] = m1 * span;
        piece.c[2] = 3 * (q2 - q1) - 2 * m1 * span - m2 * span;
        piece.c[3] = 2 * (q1 - q2) + m1 * span + m2 * span;
        double lo, hi;
        cubicRange(piece.c, lo, hi);
        piece.r2Max = std::max(0.0, hi);
        pieces_.push_back(piece);
    }
    bottom_ = pts[1].v;
    top_ = pts[pts.size() - 2].v;
    bottomR2_ = pts[1].u * pts[1].u;
    topR2_ = pts[pts.size() - 2].u * pts[pts.size() - 2].u;
    double r2 = 0;
    for (const Piece& piece : pieces_) r2 = std::max(r2, piece.r2Max);
    const double r = std::sqrt(r2);
    bounds_ = {{-r, bottom_, -r}, {r, top_, r}};
}

const Sor::Piece* Sor::pieceAt(double h) const {
    if (pieces_.empty()) return nullptr;
    for (const Piece& piece : pieces_)
        if (h <= piece.h1) return &piece;
    return &pieces_.back();
}

double Sor::radius2At(const Piece& piece, double h) const {
    return poly3(piece.c, (h - piece.h0) / (piece.h1 - piece.h0));
}

void Sor::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    const AxisDistance rho(ray);
    const double py = ray.origin.y, dy = ray.direction.y;
    std::vector<double> found;
    for (const Piece& piece : pieces_) {
        double t0, t1;
        if (!heightInterval(ray, piece.h0, piece.h1, t0, t1)) continue;
        t0 = std::max(t0, tMin);
        t1 = std::min(t1, tMax);
        if (t0 > t1 || rho.minOver(t0, t1) > piece.r2Max * (1 + 1e-9)) continue;
        const double span = piece.h1 - piece.h0;
        const double s0 = (py - piece.h0) / span;
        if (dy == 0) {
            double tq[2];
            const int m = solveQuadratic(rho.c - poly3(piece.c, s0), 2 * rho.b, rho.a, tq);
            for (int j = 0; j < m; ++j) found.push_back(tq[j]);
            continue;
        }
        // r^2(s0 + k t) in powers of t, then rho^2(t) - r^2 = 0.
        const double k = dy / span;
        const double* c = piece.c;
        double q[4];
        q[0] = poly3(c, s0);
        q[1] = slope3(c, s0) * k;
        q[2] = (c[2] + 3 * c[3] * s0) * k * k;
        q[3] = c[3] * k * k * k;
        double eq[4] = {rho.c - q[0], 2 * rho.b - q[1], rho.a - q[2], -q[3]};
        int degree = 3;
        while (degree > 0 && eq[degree] == 0) --degree;
        if (degree == 0) continue;
        // A hair beyond the piece so a hit on a joint is not lost between
        // two pieces.
        const double pad = 1e-9 * std::max(1.0, std::fabs(t1 - t0));
        double roots[3];
        const int n =
            realRootsInInterval(std::span<const double>(eq, static_cast<size_t>(degree) + 1),
                                t0 - pad, t1 + pad, roots);
        for (int i = 0; i < n; ++i) found.push_back(roots[i]);
    }
    if (!open_ && dy != 0) {
        for (const double h : {bottom_, top_}) {
            const double t = (h - py) / dy;
            if (rho.at(t) <= (h == bottom_ ? bottomR2_ : topR2_)) found.push_back(t);
        }
    }
    detail::appendDistinctHits(found, tMin, tMax, ts);
}

// povray 3.7's sor uv (measured): u around the axis as a sphere's; on the
// side v as the lathe's, each piece an equal share by its height
// fraction; on the caps v is the distance from the axis over the cap's
// radius (the top cap's counted from 1 down).
bool Sor::uv(const Vec3& p, double& u, double& v) const {
    const Vec3 n = normal(p);
    if (!open_ && n.x == 0 && n.z == 0 && (n.y == 1 || n.y == -1)) {
        const double rho = std::sqrt(p.x * p.x + p.z * p.z);
        u = turnsAroundY(p);
        if (n.y < 0)
            v = bottomR2_ > 0 ? rho / std::sqrt(bottomR2_) : 0;
        else
            v = topR2_ > 0 ? 1 - rho / std::sqrt(topR2_) : 0;
        return true;
    }
    u = turnsAroundY(p);
    v = 0;
    const Piece* piece = pieceAt(p.y);
    if (!piece) return true;
    const double s = std::clamp((p.y - piece->h0) / (piece->h1 - piece->h0), 0.0, 1.0);
    v = (static_cast<double>(piece - pieces_.data()) + s) / static_cast<double>(pieces_.size());
    return true;
}

Vec3 Sor::normal(const Vec3& p) const {
    const Piece* piece = pieceAt(p.y);
    if (!piece) return {0, 1, 0};
    const double rho2 = p.x * p.x + p.z * p.z;
    const double r2 = radius2At(*piece, p.y);
    if (!open_) {
        // A cap when the point is nearer to the cap's plane than to the side.
        const double side = std::fabs(std::sqrt(rho2) - std::sqrt(std::max(0.0, r2)));
        if (std::fabs(p.y - bottom_) < side && rho2 <= bottomR2_ * (1 + 1e-9)) return {0, -1, 0};
        if (std::fabs(p.y - top_) < side && rho2 <= topR2_ * (1 + 1e-9)) return {0, 1, 0};
    }
    // Gradient of x^2 + z^2 - r^2(y).
    const double span = piece->h1 - piece->h0;
    const double dr2 = slope3(piece->c, (p.y - piece->h0) / span) / span;
    const Vec3 n{2 * p.x, -dr2, 2 * p.z};
    const double len = length(n);
    return len > 0 ? n / len : Vec3(0, 1, 0);
}

bool Sor::inside(const Vec3& p) const {
    if (p.y < bottom_ || p.y > top_) return false;
    const Piece* piece = pieceAt(p.y);
    return piece && p.x * p.x + p.z * p.z < radius2At(*piece, p.y);
}

}  // namespace frameray::scene
