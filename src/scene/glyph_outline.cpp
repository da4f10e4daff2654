#include "scene/glyph_outline.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene/shape_math.h"

namespace frameray::scene {

namespace {

Point2 operator-(Point2 a, Point2 b) {
    return {a.x - b.x, a.y - b.y};
}
double cross2(Point2 a, Point2 b) {
    return a.x * b.y - a.y * b.x;
}
double dot2(Point2 a, Point2 b) {
    return a.x * b.x + a.y * b.y;
}

// Power-basis coefficients c[0] + c[1] s + c[2] s^2 + c[3] s^3 of one
// coordinate of a Bezier segment.
void powerBasis(const OutlineSegment& seg, double Point2::*axis, double c[4]) {
    const double p0 = seg.p[0].*axis, p1 = seg.p[1].*axis;
    c[2] = c[3] = 0;
    switch (seg.degree) {
        case 1:
            c[0] = p0;
            c[1] = p1 - p0;
            break;
        case 2: {
            const double p2 = seg.p[2].*axis;
            c[0] = p0;
            c[1] = 2 * (p1 - p0);
            c[2] = p0 - 2 * p1 + p2;
            break;
        }
        default: {
            const double p2 = seg.p[2].*axis, p3 = seg.p[3].*axis;
            c[0] = p0;
            c[1] = 3 * (p1 - p0);
            c[2] = 3 * (p0 - 2 * p1 + p2);
            c[3] = -p0 + 3 * (p1 - p2) + p3;
            break;
        }
    }
}

double evalPoly(const double c[4], double s) {
    return ((c[3] * s + c[2]) * s + c[1]) * s + c[0];
}

// Roots in [0, 1] of the polynomial c (degree up to 3), written to
// `roots` (at most 3); returns how many. Quadratics are solved in closed form; cubics are split at
// the turning points into monotone intervals, each searched by bisection.
int rootsInUnitInterval(const double c[4], double roots[3]) {
    int found = 0;
    if (c[3] == 0) {
        double r0, r1;
        const int n = detail::solveQuadratic(c[2], c[1], c[0], r0, r1);
        if (n >= 1 && r0 >= 0 && r0 <= 1) roots[found++] = r0;
        if (n == 2 && r1 != r0 && r1 >= 0 && r1 <= 1) roots[found++] = r1;
        return found;
    }
    double splits[4] = {0, 0, 0, 1};
    int count = 1;
    double e0, e1;
    const int n = detail::solveQuadratic(3 * c[3], 2 * c[2], c[1], e0, e1);
    if (n >= 1 && e0 > 0 && e0 < 1) splits[count++] = e0;
    if (n == 2 && e1 > 0 && e1 < 1 && e1 != e0) splits[count++] = e1;
    splits[count++] = 1;
    for (int i = 0; i + 1 < count; ++i) {
        double lo = splits[i], hi = splits[i + 1];
        double flo = evalPoly(c, lo), fhi = evalPoly(c, hi);
        // Each interval owns its start; the last one also its end.
        if (flo == 0) {
            roots[found++] = lo;
            continue;
        }
        if (fhi == 0) {
            if (i + 2 == count) roots[found++] = hi;
            continue;
        }
        if ((flo < 0) == (fhi < 0)) continue;
        for (int it = 0; it < 64 && hi - lo > 1e-15; ++it) {
            const double mid = 0.5 * (lo + hi);
            const double fm = evalPoly(c, mid);
            if ((fm < 0) == (flo < 0)) {
                lo = mid;
                flo = fm;
            } else {
                hi = mid;
            }
        }
        roots[found++] = 0.5 * (lo + hi);
    }
    return found;
}

// Parameter of the point of `seg` nearest q: the best of a few samples,
// polished by Newton steps on (B(s) - q) . B'(s) = 0.
double nearestParameter(const OutlineSegment& seg, Point2 q) {
    if (seg.degree == 1) {
        const Point2 e = seg.p[1] - seg.p[0];
        const double len2 = dot2(e, e);
        if (len2 == 0) return 0;
        return std::clamp(dot2(q - seg.p[0], e) / len2, 0.0, 1.0);
    }
    constexpr int kSamples = 16;
    double best = 0, bestD2 = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= kSamples; ++i) {
        const double s = static_cast<double>(i) / kSamples;
        const Point2 v = seg.at(s) - q;
        const double d2 = dot2(v, v);
        if (d2 < bestD2) {
            bestD2 = d2;
            best = s;
        }
    }
    double cx[4], cy[4];
    powerBasis(seg, &Point2::x, cx);
    powerBasis(seg, &Point2::y, cy);
    double s = best;
    for (int it = 0; it < 8; ++it) {
        const Point2 v = seg.at(s) - q;
        const Point2 d1 = seg.derivative(s);
        const Point2 d2{2 * cx[2] + 6 * cx[3] * s, 2 * cy[2] + 6 * cy[3] * s};
        const double g = dot2(v, d1);
        const double gp = dot2(d1, d1) + dot2(v, d2);
        if (gp <= 0) break;
        const double next = std::clamp(s - g / gp, 0.0, 1.0);
        if (next == s) break;
        s = next;
    }
    return s;
}

double distanceToBox(const Box2& b, double x, double y) {
    const double dx = std::max({b.xlo - x, 0.0, x - b.xhi});
    const double dy = std::max({b.ylo - y, 0.0, y - b.yhi});
    return std::sqrt(dx * dx + dy * dy);
}

Box2 controlBox(const OutlineSegment& seg) {
    Box2 b;
    for (int i = 0; i <= seg.degree; ++i) b.extend(seg.p[i]);
    return b;
}

}  // namespace

Point2 OutlineSegment::at(double s) const {
    const double u = 1 - s;
    switch (degree) {
        case 1:
            return {p[0].x + s * (p[1].x - p[0].x), p[0].y + s * (p[1].y - p[0].y)};
        case 2: {
            const double a = u * u, b = 2 * s * u, c = s * s;
            return {a * p[0].x + b * p[1].x + c * p[2].x, a * p[0].y + b * p[1].y + c * p[2].y};
        }
        default: {
            const double a = u * u * u, b = 3 * s * u * u, c = 3 * s * s * u, d = s * s * s;
            return {a * p[0].x + b * p[1].x + c * p[2].x + d * p[3].x,
                    a * p[0].y + b * p[1].y + c * p[2].y + d * p[3].y};
        }
    }
}

Point2 OutlineSegment::derivative(double s) const {
    const double u = 1 - s;
    switch (degree) {
        case 1:
            return p[1] - p[0];
        case 2: {
            const Point2 a = p[1] - p[0], b = p[2] - p[1];
            return {2 * (u * a.x + s * b.x), 2 * (u * a.y + s * b.y)};
        }
        default: {
            const Point2 a = p[1] - p[0], b = p[2] - p[1], c = p[3] - p[2];
            return {3 * (u * u * a.x + 2 * s * u * b.x + s * s * c.x),
                    3 * (u * u * a.y + 2 * s * u * b.y + s * s * c.y)};
        }
    }
}

void Box2::extend(const Point2& p) {
    xlo = std::min(xlo, p.x);
    xhi = std::max(xhi, p.x);
    ylo = std::min(ylo, p.y);
    yhi = std::max(yhi, p.y);
}

GlyphOutline::GlyphOutline(std::vector<OutlineSegment> segments) : segments_(std::move(segments)) {
    segmentBoxes_.reserve(segments_.size());
    for (uint32_t i = 0; i < segments_.size(); ++i) {
        const OutlineSegment& seg = segments_[i];
        const Box2 b = controlBox(seg);
        segmentBoxes_.push_back(b);
        box_.extend({b.xlo, b.ylo});
        box_.extend({b.xhi, b.yhi});

        // Split at the parameters where y turns, so each piece crosses a
        // horizontal line at most once.
        double cuts[4] = {0, 0, 0, 0};
        int cutCount = 0;
        cuts[cutCount++] = 0;
        if (seg.degree > 1) {
            double cy[4];
            powerBasis(seg, &Point2::y, cy);
            double r0 = -1, r1 = -1;
            const int n = detail::solveQuadratic(3 * cy[3], 2 * cy[2], cy[1], r0, r1);
            double turns[2];
            int turnCount = 0;
            if (n >= 1 && r0 > 0 && r0 < 1) turns[turnCount++] = r0;
            if (n == 2 && r1 > 0 && r1 < 1 && r1 != r0) turns[turnCount++] = r1;
            if (turnCount == 2 && turns[1] < turns[0]) std::swap(turns[0], turns[1]);
            for (int t = 0; t < turnCount; ++t) cuts[cutCount++] = turns[t];
        }
        cuts[cutCount++] = 1;
        for (int c = 0; c + 1 < cutCount; ++c) {
            const double s0 = cuts[c], s1 = cuts[c + 1];
            // Exact end points at the segment's ends, so that consecutive
            // pieces of a contour meet at bit-identical heights.
            const double ya = s0 == 0 ? seg.p[0].y : seg.at(s0).y;
            const double yb = s1 == 1 ? seg.p[seg.degree].y : seg.at(s1).y;
            if (ya == yb) continue;  // horizontal: never crossed by a horizontal ray
            pieces_.push_back({i, s0, s1, ya, yb, b.xlo, b.xhi});
        }
    }
    buildBands();
}

int GlyphOutline::bandOf(double y) const {
    const double k = std::floor((y - bandY0_) * bandInvHeight_);
    if (!(k > 0)) return 0;  // also NaN
    return k >= bandCount_ ? bandCount_ - 1 : static_cast<int>(k);
}

void GlyphOutline::buildBands() {
    if (segments_.empty()) {
        bandCount_ = 1;
        segmentStart_.assign(2, 0);
        pieceStart_.assign(2, 0);
        return;
    }
    const double height = box_.yhi - box_.ylo;
    bandCount_ = std::clamp(static_cast<int>(segments_.size() / 3), 1, 64);
    if (!(height > 0)) bandCount_ = 1;
    bandY0_ = box_.ylo;
    bandInvHeight_ = bandCount_ > 1 ? bandCount_ / height : 0;
    // Ranges are widened a little so a point computed on a curve, which
    // may stray from it by rounding, still finds the curve in its band.
    const double pad = 1e-9 * std::max(height, box_.xhi - box_.xlo) + 1e-12;

    auto fill = [&](size_t count, auto rangeOf, std::vector<uint32_t>& start,
                    std::vector<uint32_t>& items) {
        std::vector<uint32_t> counts(static_cast<size_t>(bandCount_) + 1, 0);
        for (size_t i = 0; i < count; ++i) {
            const auto [lo, hi] = rangeOf(i);
            for (int k = bandOf(lo - pad); k <= bandOf(hi + pad); ++k)
                ++counts[static_cast<size_t>(k) + 1];
        }
        for (size_t k = 1; k < counts.size(); ++k) counts[k] += counts[k - 1];
        start = counts;
        items.assign(counts.back(), 0);
        for (size_t i = 0; i < count; ++i) {
            const auto [lo, hi] = rangeOf(i);
            for (int k = bandOf(lo - pad); k <= bandOf(hi + pad); ++k)
                items[counts[static_cast<size_t>(k)]++] = static_cast<uint32_t>(i);
        }
    };
    fill(
        segments_.size(),
        [&](size_t i) {
            return std::pair{segmentBoxes_[i].ylo, segmentBoxes_[i].yhi};
        },
        segmentStart_, segmentItems_);
    fill(
        pieces_.size(),
        [&](size_t i) {
            return std::pair{std::min(pieces_[i].ya, pieces_[i].yb),
                             std::max(pieces_[i].ya, pieces_[i].yb)};
        },
        pieceStart_, pieceItems_);
}

double GlyphOutline::pieceCrossingX(const Piece& piece, double y) const {
    const OutlineSegment& seg = segments_[piece.segment];
    if (seg.degree == 1) {
        const double s = (y - seg.p[0].y) / (seg.p[1].y - seg.p[0].y);
        return seg.p[0].x + s * (seg.p[1].x - seg.p[0].x);
    }
    double cy[4];
    powerBasis(seg, &Point2::y, cy);
    cy[0] -= y;
    if (seg.degree == 2) {
        double r0, r1;
        const int n = detail::solveQuadratic(cy[2], cy[1], cy[0], r0, r1);
        // The root inside the piece (the other, if any, is outside it).
        const double slack = 1e-9;
        for (int i = 0; i < n; ++i) {
            const double r = i == 0 ? r0 : r1;
            if (r >= piece.s0 - slack && r <= piece.s1 + slack)
                return seg.at(std::clamp(r, piece.s0, piece.s1)).x;
        }
    }
    // Monotone in y over the piece: bisection always converges.
    double lo = piece.s0, hi = piece.s1;
    const bool rising = piece.yb > piece.ya;
    for (int it = 0; it < 64 && hi - lo > 1e-15; ++it) {
        const double mid = 0.5 * (lo + hi);
        if ((evalPoly(cy, mid) < 0) == rising)
            lo = mid;
        else
            hi = mid;
    }
    return seg.at(0.5 * (lo + hi)).x;
}

bool GlyphOutline::contains(double x, double y) const {
    if (segments_.empty() || x < box_.xlo || x > box_.xhi || y < box_.ylo || y > box_.yhi)
        return false;
    const int k = bandOf(y);
    bool inside = false;
    for (uint32_t i = pieceStart_[static_cast<size_t>(k)];
         i < pieceStart_[static_cast<size_t>(k) + 1]; ++i) {
        const Piece& piece = pieces_[pieceItems_[i]];
        // Half-open in y, so a ray through a vertex where the outline goes
        // on upwards (or downwards) counts one crossing, and none (or two)
        // where it turns back.
        const double lo = std::min(piece.ya, piece.yb), hi = std::max(piece.ya, piece.yb);
        if (y < lo || y >= hi) continue;
        if (piece.xhi <= x) continue;
        if (piece.xlo > x || pieceCrossingX(piece, y) > x) inside = !inside;
    }
    return inside;
}

void GlyphOutline::lineCrossings(Point2 o, Point2 d, double t0, double t1,
                                 std::vector<double>& ts) const {
    if (segments_.empty() || !(t0 <= t1)) return;
    const Point2 a{o.x + t0 * d.x, o.y + t0 * d.y}, b{o.x + t1 * d.x, o.y + t1 * d.y};
    const double lxlo = std::min(a.x, b.x), lxhi = std::max(a.x, b.x);
    const double lylo = std::min(a.y, b.y), lyhi = std::max(a.y, b.y);
    if (lxhi < box_.xlo || lxlo > box_.xhi || lyhi < box_.ylo || lylo > box_.yhi) return;
    const double dd = dot2(d, d);
    if (dd == 0) return;
    // Implicit form of the line: n . (p - o) = 0.
    const Point2 n{d.y, -d.x};
    const int kFirst = std::max(0, bandOf(lylo) - 1),
              kLast = std::min(bandCount_ - 1, bandOf(lyhi) + 1);
    double roots[8];
    for (int k = kFirst; k <= kLast; ++k) {
        for (uint32_t j = segmentStart_[static_cast<size_t>(k)];
             j < segmentStart_[static_cast<size_t>(k) + 1]; ++j) {
            const uint32_t i = segmentItems_[j];
            const Box2& sb = segmentBoxes_[i];
            if (sb.xhi < lxlo || sb.xlo > lxhi || sb.yhi < lylo || sb.ylo > lyhi) continue;
            // All four box corners on one side of the line: no crossing.
            const double c0 = dot2(n, Point2{sb.xlo, sb.ylo} - o),
                         c1 = dot2(n, Point2{sb.xhi, sb.ylo} - o);
            const double c2 = dot2(n, Point2{sb.xlo, sb.yhi} - o),
                         c3 = dot2(n, Point2{sb.xhi, sb.yhi} - o);
            if ((c0 > 0 && c1 > 0 && c2 > 0 && c3 > 0) || (c0 < 0 && c1 < 0 && c2 < 0 && c3 < 0))
                continue;

            const OutlineSegment& seg = segments_[i];
            int rootCount = 0;
            if (seg.degree == 1) {
                const Point2 e = seg.p[1] - seg.p[0];
                const double den = cross2(e, d);
                if (std::fabs(den) <= 1e-14 * std::sqrt(dot2(e, e) * dd)) continue;  // parallel
                const double s = cross2(o - seg.p[0], d) / den;
                if (s < 0 || s > 1) continue;
                roots[rootCount++] = s;
            } else {
                double cx[4], cy[4], f[4];
                powerBasis(seg, &Point2::x, cx);
                powerBasis(seg, &Point2::y, cy);
                for (int c = 0; c < 4; ++c) f[c] = n.x * cx[c] + n.y * cy[c];
                f[0] -= dot2(n, o);
                rootCount = rootsInUnitInterval(f, roots);
            }
            for (int r = 0; r < rootCount; ++r) {
                const Point2 q = seg.at(roots[r]);
                // A segment reaching into several bands is met in each:
                // its crossing belongs to the band of its height only.
                if (bandOf(q.y) != k) continue;
                ts.push_back(dot2(q - o, d) / dd);
            }
        }
    }
}

double GlyphOutline::nearestEdge(double x, double y, Point2& direction) const {
    double best = std::numeric_limits<double>::infinity();
    direction = {1, 0};
    if (segments_.empty()) return best;
    const Point2 q{x, y};
    auto consider = [&](uint32_t i) {
        if (distanceToBox(segmentBoxes_[i], x, y) >= best) return;
        const OutlineSegment& seg = segments_[i];
        const double s = nearestParameter(seg, q);
        const Point2 v = seg.at(s) - q;
        const double dist = std::sqrt(dot2(v, v));
        if (dist < best) {
            best = dist;
            direction = seg.derivative(s);
            // A degenerate tangent (a control point on an end point): use
            // the chord instead.
            if (direction.x == 0 && direction.y == 0) direction = seg.p[seg.degree] - seg.p[0];
        }
    };
    const int k = bandOf(y);
    const int kFirst = std::max(0, k - 1), kLast = std::min(bandCount_ - 1, k + 1);
    for (int b = kFirst; b <= kLast; ++b)
        for (uint32_t j = segmentStart_[static_cast<size_t>(b)];
             j < segmentStart_[static_cast<size_t>(b) + 1]; ++j)
            consider(segmentItems_[j]);
    // The neighbouring bands hold the edges of any point on or near the
    // outline; a point farther away searches everything.
    const double bandHeight =
        bandInvHeight_ > 0 ? 1 / bandInvHeight_ : std::numeric_limits<double>::infinity();
    if (best > bandHeight)
        for (uint32_t i = 0; i < segments_.size(); ++i) consider(i);
    return best;
}

}  // namespace frameray::scene
