#include "scene/sphere_sweep.h"

#include <algorithm>
#include <cmath>

#include "scene/implicit_search.h"
#include "scene/shape_math.h"

namespace frameray::scene {

namespace {

Vec3 cubicAt(const Vec3 c[4], double s) {
    return ((c[3] * s + c[2]) * s + c[1]) * s + c[0];
}
double cubicAt(const double c[4], double s) {
    return ((c[3] * s + c[2]) * s + c[1]) * s + c[0];
}

Bounds ballBox(const SweepPoint& b) {
    return {b.center - Vec3(b.radius), b.center + Vec3(b.radius)};
}

// Parameter in [0, 1] of the sphere nearest to p (by surface distance)
// on the linear sweep from `a` to `b`: where d/ds (|p - c(s)| - r(s)) = 0.
double closestOnLinearSweep(const SweepPoint& a, const SweepPoint& b, const Vec3& p) {
    const Vec3 axis = b.center - a.center;
    const double len = length(axis);
    if (len == 0) return b.radius > a.radius ? 1 : 0;
    const Vec3 dir = axis / len;
    const Vec3 w = p - a.center;
    const double u = dot(w, dir);
    const double v = length(w - dir * u);
    const double k = (b.radius - a.radius) / len;
    if (std::fabs(k) >= 1) return k > 0 ? 1 : 0;
    return std::clamp((u + k * v / std::sqrt(1 - k * k)) / len, 0.0, 1.0);
}

}  // namespace

SphereSweep::SphereSweep(SweepSpline kind, const std::vector<SweepPoint>& p) : kind_(kind) {
    auto setSegment = [&](const SweepPoint* q, Segment& seg) {
        switch (kind) {
            case SweepSpline::Linear:
                seg.c[0] = q[0].center;
                seg.c[1] = q[1].center - q[0].center;
                seg.c[2] = seg.c[3] = Vec3();
                seg.r[0] = q[0].radius;
                seg.r[1] = q[1].radius - q[0].radius;
                seg.r[2] = seg.r[3] = 0;
                break;
            case SweepSpline::BSpline: {
                // Uniform cubic B-spline, in powers of s.
                auto basis = [](auto p0, auto p1, auto p2, auto p3, auto* c) {
                    c[0] = (p0 + 4 * p1 + p2) / 6;
                    c[1] = (p2 - p0) / 2;
                    c[2] = (p0 - 2 * p1 + p2) / 2;
                    c[3] = (-1 * p0 + 3 * p1 - 3 * p2 + p3) / 6;
                };
                basis(q[0].center, q[1].center, q[2].center, q[3].center, seg.c);
                basis(q[0].radius, q[1].radius, q[2].radius, q[3].radius, seg.r);
                break;
            }
            case SweepSpline::CatmullRom: {
                // Through q1 and q2 with slopes (q2 - q0) / 2, (q3 - q1) / 2.
                auto hermite = [](auto p0, auto p1, auto p2, auto p3, auto* c) {
                    const auto m1 = (p2 - p0) / 2, m2 = (p3 - p1) / 2;
                    c[0] = p1;
                    c[1] = m1;
                    c[2] = 3 * (p2 - p1) - 2 * m1 - m2;
                    c[3] = 2 * (p1 - p2) + m1 + m2;
                };
                hermite(q[0].center, q[1].center, q[2].center, q[3].center, seg.c);
                hermite(q[0].radius, q[1].radius, q[2].radius, q[3].radius, seg.r);
                break;
            }
        }
    };
    const size_t per = kind == SweepSpline::Linear ? 2 : 4;
    for (size_t i = 0; i + per <= p.size(); ++i) {
        Segment seg;
        setSegment(&p[i], seg);
        segments_.push_back(seg);
    }
    const int pieces = kind == SweepSpline::Linear ? 1 : kPiecesPerSegment;
    for (size_t si = 0; si < segments_.size(); ++si) {
        segments_[si].firstPiece = pieces_.size();
        for (int k = 0; k < pieces; ++k) {
            Piece piece;
            piece.segment = si;
            piece.s0 = static_cast<double>(k) / pieces;
            piece.s1 = static_cast<double>(k + 1) / pieces;
            piece.from = sphereAt(si, piece.s0);
            piece.to = sphereAt(si, piece.s1);
            // The cone tangent to both balls: along the axis it starts
            // -r0 k and ends L - r1 k from the first centre, with radii
            // r sqrt(1 - k^2), k = (r1 - r0) / L.
            const Vec3 axis = piece.to.center - piece.from.center;
            const double len = length(axis);
            const double slope = len > 0 ? (piece.to.radius - piece.from.radius) / len : 2;
            if (std::fabs(slope) < 1) {
                const Vec3 dir = axis / len;
                const double f = std::sqrt(1 - slope * slope);
                const Vec3 base = piece.from.center - dir * (piece.from.radius * slope);
                const Vec3 cap = piece.to.center - dir * (piece.to.radius * slope);
                const double rb = piece.from.radius * f, rc = piece.to.radius * f;
                if (rb > 0 || rc > 0)
                    piece.cone.emplace(base, std::max(rb, 0.0), cap, std::max(rc, 0.0), false);
            }
            piece.box = ballBox(piece.from);
            piece.box.extend(ballBox(piece.to));
            bounds_.extend(piece.box);
            segments_[si].box.extend(piece.box);
            pieces_.push_back(std::move(piece));
        }
        segments_[si].endPiece = pieces_.size();
    }
    last_ = pieces_.empty() ? SweepPoint{} : pieces_.back().to;
}

SweepPoint SphereSweep::sphereAt(size_t segment, double s) const {
    const Segment& seg = segments_[segment];
    return {cubicAt(seg.c, s), std::fabs(cubicAt(seg.r, s))};
}

double SphereSweep::sweepDistance(const Vec3& p, size_t seg, double s) const {
    const SweepPoint b = sphereAt(seg, s);
    return length(p - b.center) - b.radius;
}

void SphereSweep::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    // The shape is the union of convex parts (balls and capped cones):
    // merge the intervals the ray spends in each and report the ends.
    std::vector<std::pair<double, double>> spans;
    std::vector<double> cone;
    auto addBall = [&](const SweepPoint& b) {
        double t0, t1;
        if (detail::distanceRoots(ray.origin - b.center, ray.direction, b.radius * b.radius, t0,
                                  t1) &&
            t1 > tMin && t0 < tMax && t1 > t0)
            spans.emplace_back(t0, t1);
    };
    auto missed = [&](const Bounds& box) {
        double b0, b1;
        return !detail::clipToBox(ray, box.lo, box.hi, b0, b1) || b1 < tMin || b0 > tMax;
    };
    for (const Segment& seg : segments_) {
        if (missed(seg.box)) continue;
        for (size_t i = seg.firstPiece; i < seg.endPiece; ++i) {
            const Piece& piece = pieces_[i];
            if (missed(piece.box)) continue;
            addBall(piece.from);
            if (piece.cone) {
                cone.clear();
                piece.cone->allHits(ray, -kInfinity, kInfinity, cone);
                if (cone.size() >= 2 && cone.back() > tMin && cone.front() < tMax)
                    spans.emplace_back(cone.front(), cone.back());
            }
        }
    }
    if (!pieces_.empty()) addBall(last_);
    if (spans.empty()) return;
    std::sort(spans.begin(), spans.end());
    double a = spans[0].first, b = spans[0].second;
    auto emit = [&](double lo, double hi) {
        if (lo > tMin && lo < tMax) ts.push_back(lo);
        if (hi > tMin && hi < tMax) ts.push_back(hi);
    };
    for (size_t i = 1; i < spans.size(); ++i) {
        if (spans[i].first <= b) {
            b = std::max(b, spans[i].second);
        } else {
            emit(a, b);
            a = spans[i].first;
            b = spans[i].second;
        }
    }
    emit(a, b);
}

Vec3 SphereSweep::normal(const Vec3& p) const {
    // The swept sphere the point lies on is the one it is nearest to (by
    // surface distance): pick the piece, then refine on the spline.
    double best = kInfinity;
    size_t bestPiece = 0;
    double bestS = 0;
    for (size_t i = 0; i < pieces_.size(); ++i) {
        const Piece& piece = pieces_[i];
        const double s = closestOnLinearSweep(piece.from, piece.to, p);
        const Vec3 c = piece.from.center + (piece.to.center - piece.from.center) * s;
        const double r = piece.from.radius + (piece.to.radius - piece.from.radius) * s;
        const double d = length(p - c) - r;
        if (d < best) {
            best = d;
            bestPiece = i;
            bestS = s;
        }
    }
    if (pieces_.empty()) return {0, 1, 0};
    const Piece& piece = pieces_[bestPiece];
    double s = piece.s0 + (piece.s1 - piece.s0) * bestS;
    if (kind_ != SweepSpline::Linear) {
        // Golden-section search of the surface distance around the piece.
        const double width = piece.s1 - piece.s0;
        double lo = std::max(0.0, s - width), hi = std::min(1.0, s + width);
        constexpr double kGolden = 0.6180339887498949;
        double x1 = hi - kGolden * (hi - lo), x2 = lo + kGolden * (hi - lo);
        double f1 = sweepDistance(p, piece.segment, x1), f2 = sweepDistance(p, piece.segment, x2);
        for (int it = 0; it < 40; ++it) {
            if (f1 < f2) {
                hi = x2;
                x2 = x1;
                f2 = f1;
                x1 = hi - kGolden * (hi - lo);
                f1 = sweepDistance(p, piece.segment, x1);
            } else {
                lo = x1;
                x1 = x2;
                f1 = f2;
                x2 = lo + kGolden * (hi - lo);
                f2 = sweepDistance(p, piece.segment, x2);
            }
        }
        s = 0.5 * (lo + hi);
    }
    const Vec3 n = p - sphereAt(piece.segment, s).center;
    const double len = length(n);
    return len > 0 ? n / len : Vec3(0, 1, 0);
}

bool SphereSweep::inside(const Vec3& p) const {
    auto inBall = [&](const SweepPoint& b) {
        const Vec3 d = p - b.center;
        return dot(d, d) < b.radius * b.radius;
    };
    for (const Piece& piece : pieces_) {
        if (p.x < piece.box.lo.x || p.x > piece.box.hi.x || p.y < piece.box.lo.y ||
            p.y > piece.box.hi.y || p.z < piece.box.lo.z || p.z > piece.box.hi.z)
            continue;
        if (inBall(piece.from) || (piece.cone && piece.cone->inside(p))) return true;
    }
    return !pieces_.empty() && inBall(last_);
}

}  // namespace frameray::scene
