// The 2-D outline of one font glyph, in em units, with the queries the
// text shape asks of it: is a point inside (even-odd, as POV-Ray 3.7
// counts crossings), where does a line cross the outline, and which
// outline edge is nearest a point (for the surface normal).
//
// Outlines are built once per glyph when a font is read and never change,
// so every text shape (and every render thread) shares them. A glyph has
// tens to hundreds of curves; to avoid testing each of them for every ray,
// the outline is cut into horizontal bands, each listing the curves that
// reach into it: a point query looks at one band, a line only at the bands
// its y-range covers.
#pragma once

#include <cstdint>
#include <vector>

namespace frameray::scene {

struct Point2 {
    double x = 0, y = 0;
};

// One piece of an outline: a line (degree 1) or a quadratic (TrueType) or
// cubic (CFF) Bezier curve. p[0] is the start, p[degree] the end.
struct OutlineSegment {
    int degree = 1;
    Point2 p[4];

    Point2 at(double s) const;
    Point2 derivative(double s) const;
};

// An axis-aligned 2-D box; empty when lo > hi.
struct Box2 {
    double xlo = 1e300, ylo = 1e300, xhi = -1e300, yhi = -1e300;

    bool isEmpty() const { return xlo > xhi || ylo > yhi; }
    void extend(const Point2& p);
};

class GlyphOutline {
  public:
    // The segments of closed contours, in contour order.
    explicit GlyphOutline(std::vector<OutlineSegment> segments);

    bool empty() const { return segments_.empty(); }
    const std::vector<OutlineSegment>& segments() const { return segments_; }
    // Box of every segment's control points: nothing of the outline lies
    // outside it.
    const Box2& box() const { return box_; }

    // Whether (x, y) is inside by the even-odd rule: an odd number of
    // outline crossings to its right. POV-Ray 3.7 counts crossings, so
    // overlapping contours cancel, whatever their direction.
    bool contains(double x, double y) const;

    // Every point where the line o + t d, for t in [t0, t1], meets the
    // outline: appends each t to `ts` (unsorted). Curves count where they
    // cross or touch the line at a parameter in [0, 1].
    void lineCrossings(Point2 o, Point2 d, double t0, double t1, std::vector<double>& ts) const;

    // The outline edge nearest (x, y): returns the distance to it and sets
    // `direction` to the edge's tangent there (in contour direction; its
    // left-hand normal (-dy, dx) is what POV-Ray uses as the wall normal).
    double nearestEdge(double x, double y, Point2& direction) const;

  private:
    // A y-monotone part of a segment (curves are split at their vertical
    // turning points), used for the crossing count.
    struct Piece {
        uint32_t segment;
        double s0, s1;    // parameter range, s0 < s1
        double ya, yb;    // y at s0 and at s1 (ya != yb)
        double xlo, xhi;  // bounds of the control points over the piece
    };
    int bandOf(double y) const;
    void buildBands();
    double pieceCrossingX(const Piece& piece, double y) const;

    std::vector<OutlineSegment> segments_;
    std::vector<Box2> segmentBoxes_;
    std::vector<Piece> pieces_;
    Box2 box_;
    // Bands: band k covers y in [bandY0_ + k h, bandY0_ + (k+1) h). Each
    // band lists the segments and pieces that reach into it, stored as
    // contiguous runs: band k's are items[start[k] .. start[k+1]).
    int bandCount_ = 1;
    double bandY0_ = 0, bandInvHeight_ = 0;
    std::vector<uint32_t> segmentStart_, segmentItems_;
    std::vector<uint32_t> pieceStart_, pieceItems_;
};

}  // namespace frameray::scene
