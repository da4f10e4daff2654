#include "scene/ttf_font.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include FT_TRUETYPE_TABLES_H
#include FT_TRUETYPE_TAGS_H

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace frameray::scene {

namespace {

// Big-endian reads from a table held in memory; reading past the end
// gives zeros (a damaged font reads as empty rather than crashing).
struct TableReader {
    const std::vector<uint8_t>& bytes;
    size_t pos = 0;

    uint8_t u8() { return pos < bytes.size() ? bytes[pos++] : (++pos, uint8_t{0}); }
    uint16_t u16() {
        const uint16_t hi = u8();
        return static_cast<uint16_t>((hi << 8) | u8());
    }
    int16_t s16() { return static_cast<int16_t>(u16()); }
};

std::vector<uint8_t> loadTable(FT_Face face, FT_ULong tag) {
    FT_ULong length = 0;
    if (FT_Load_Sfnt_Table(face, tag, 0, nullptr, &length) != 0 || length == 0) return {};
    std::vector<uint8_t> bytes(length);
    if (FT_Load_Sfnt_Table(face, tag, 0, bytes.data(), &length) != 0) return {};
    return bytes;
}

// Bits of a composite glyph's component flags (TrueType 'glyf' table).
constexpr uint16_t kArgsAreWords = 0x0001;
constexpr uint16_t kArgsAreXyValues = 0x0002;
constexpr uint16_t kHaveScale = 0x0008;
constexpr uint16_t kMoreComponents = 0x0020;
constexpr uint16_t kHaveXyScale = 0x0040;
constexpr uint16_t kHaveTwoByTwo = 0x0080;
constexpr uint16_t kUseMyMetrics = 0x0200;

// Bits of a kern subtable's coverage word.
constexpr uint16_t kKernHorizontal = 0x01;
constexpr uint16_t kKernMinimum = 0x02;
constexpr uint16_t kKernCrossStream = 0x04;
constexpr uint16_t kKernOverride = 0x08;

// A glyph as POV-Ray 3.7 holds it before making curves of it: contours of
// points (em units) with their on-curve flags, the glyph box (font units,
// 16-bit as in the glyph header) and the glyph that gives its metrics.
struct PointGlyph {
    int16_t xMin = 0, yMin = 0, xMax = 0, yMax = 0;
    int contourCount = 0;
    std::vector<int> contourEnds;  // index of each contour's last point
    std::vector<Point2> points;
    std::vector<bool> onCurve;
    unsigned metrics = 0;
};

// povray widens the box of a composite glyph with its points, which are in
// em units by then, storing them into the 16-bit font-unit fields: the
// comparison is in doubles, the store truncates.
void widenTruncating(int16_t& field, double v, bool isMin) {
    if (isMin ? v < field : v > field) field = static_cast<int16_t>(v);
}

// The outline povray traces through a contour: from the first point, an
// on-curve point ends a line; an off-curve point is the control point of a
// quadratic ending at the next point, or halfway to it when that is off the
// curve too (the contour closes on the first point).
void contourSegments(const PointGlyph& g, int first, int last, std::vector<OutlineSegment>& out) {
    const int count = last - first + 1;
    if (count < 1) return;
    auto point = [&](int j) { return g.points[static_cast<size_t>(first + (j == count ? 0 : j))]; };
    auto on = [&](int j) {
        return static_cast<bool>(g.onCurve[static_cast<size_t>(first + (j == count ? 0 : j))]);
    };
    Point2 current = point(0);
    for (int j = 1; j <= count; ++j) {
        const Point2 p = point(j);
        if (on(j)) {
            // povray skips zero-length lines (the ones after each curve).
            if (p.x != current.x || p.y != current.y) {
                OutlineSegment seg;
                seg.degree = 1;
                seg.p[0] = current;
                seg.p[1] = p;
                out.push_back(seg);
            }
            current = p;
            continue;
        }
        Point2 end;
        if (j == count) {
            end = point(0);
        } else {
            end = point(j + 1);
            if (!on(j + 1)) end = {0.5 * (p.x + end.x), 0.5 * (p.y + end.y)};
        }
        OutlineSegment seg;
        seg.degree = 2;
        seg.p[0] = current;
        seg.p[1] = p;
        seg.p[2] = end;
        out.push_back(seg);
        current = end;
    }
}

// Collects FreeType's decomposition of an outline (CFF fonts) as segments.
struct Decomposer {
    double scale;
    Point2 current;
    std::vector<OutlineSegment> segments;

    Point2 convert(const FT_Vector* v) const {
        return {static_cast<double>(v->x) * scale, static_cast<double>(v->y) * scale};
    }
    static int moveTo(const FT_Vector* to, void* user) {
        auto* self = static_cast<Decomposer*>(user);
        self->current = self->convert(to);
        return 0;
    }
    static int lineTo(const FT_Vector* to, void* user) {
        auto* self = static_cast<Decomposer*>(user);
        OutlineSegment seg;
        seg.degree = 1;
        seg.p[0] = self->current;
        seg.p[1] = self->convert(to);
        if (seg.p[1].x != seg.p[0].x || seg.p[1].y != seg.p[0].y) self->segments.push_back(seg);
        self->current = seg.p[1];
        return 0;
    }
    static int conicTo(const FT_Vector* control, const FT_Vector* to, void* user) {
        auto* self = static_cast<Decomposer*>(user);
        OutlineSegment seg;
        seg.degree = 2;
        seg.p[0] = self->current;
        seg.p[1] = self->convert(control);
        seg.p[2] = self->convert(to);
        self->segments.push_back(seg);
        self->current = seg.p[2];
        return 0;
    }
    static int cubicTo(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
        auto* self = static_cast<Decomposer*>(user);
        OutlineSegment seg;
        seg.degree = 3;
        seg.p[0] = self->current;
        seg.p[1] = self->convert(c1);
        seg.p[2] = self->convert(c2);
        seg.p[3] = self->convert(to);
        self->segments.push_back(seg);
        self->current = seg.p[3];
        return 0;
    }
};

constexpr FT_Int32 kUnscaledOutline = FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP;

}  // namespace

struct TtfFont::Impl {
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    FT_CharMap charmap = nullptr;
    bool charmapIsFormat4 = false;
    int unitsPerEm = 1000;
    unsigned glyphCount = 0;
    // TrueType outline tables ('glyf' with 'loca'); empty for CFF fonts.
    std::vector<uint8_t> glyf;
    std::vector<uint32_t> loca;
    // hmtx, expanded to one entry per glyph as povray does.
    std::vector<std::pair<int, int>> hmtx;  // advance width, left side bearing
    struct KernSubtable {
        uint16_t coverage = 0;
        struct Pair {
            uint16_t left, right;
            int16_t value;
        };
        std::vector<Pair> pairs;
    };
    std::vector<KernSubtable> kern;

    ~Impl() {
        if (face) FT_Done_Face(face);
        if (library) FT_Done_FreeType(library);
    }

    void readTables();
    void chooseCharmap(TextCharset charset);
    unsigned glyphIndex(char32_t code) const;
    PointGlyph extract(unsigned index, char32_t code, int depth) const;
    void loadSimplePoints(unsigned dataGlyph, PointGlyph& g) const;
    TtfFont::Glyph buildGlyph(unsigned index, char32_t code) const;
    TtfFont::Glyph buildFreeTypeGlyph(unsigned index, char32_t code) const;
};

void TtfFont::Impl::readTables() {
    glyphCount = static_cast<unsigned>(face->num_glyphs);
    unitsPerEm = face->units_per_EM > 0 ? face->units_per_EM : 1000;
    if (!FT_IS_SFNT(face)) return;
    const auto* head = static_cast<const TT_Header*>(FT_Get_Sfnt_Table(face, FT_SFNT_HEAD));
    const auto* hhea = static_cast<const TT_HoriHeader*>(FT_Get_Sfnt_Table(face, FT_SFNT_HHEA));
    if (head && head->Units_Per_EM > 0) unitsPerEm = head->Units_Per_EM;

    glyf = loadTable(face, TTAG_glyf);
    const std::vector<uint8_t> locaBytes = loadTable(face, TTAG_loca);
    if (!glyf.empty() && !locaBytes.empty() && head) {
        TableReader r{locaBytes};
        const bool longOffsets = head->Index_To_Loc_Format != 0;
        loca.resize(glyphCount + 1);
        for (auto& offset : loca) {
            if (longOffsets) {
                const uint32_t hi = r.u16();
                offset = (hi << 16) | r.u16();
            } else {
                offset = static_cast<uint32_t>(r.u16()) * 2;
            }
        }
    } else {
        glyf.clear();
    }

    const std::vector<uint8_t> hmtxBytes = loadTable(face, TTAG_hmtx);
    if (!hmtxBytes.empty() && hhea) {
        TableReader r{hmtxBytes};
        const unsigned longCount = std::min<unsigned>(hhea->number_Of_HMetrics, glyphCount);
        hmtx.resize(glyphCount);
        int lastAdvance = 0;
        for (unsigned i = 0; i < glyphCount; ++i) {
            if (i < longCount) lastAdvance = r.u16();
            hmtx[i] = {lastAdvance, r.s16()};
        }
    }

    const std::vector<uint8_t> kernBytes = loadTable(face, TTAG_kern);
    if (!kernBytes.empty()) {
        TableReader r{kernBytes};
        r.u16();  // version
        const unsigned tables = r.u16();
        for (unsigned t = 0; t < tables && r.pos < kernBytes.size(); ++t) {
            const size_t start = r.pos;
            r.u16();  // subtable version
            const unsigned length = r.u16();
            KernSubtable sub;
            sub.coverage = r.u16();
            // Only format 0 (plain pairs) is read, as povray does.
            if ((sub.coverage >> 8) == 0) {
                const unsigned pairs = r.u16();
                r.pos += 6;  // searchRange, entrySelector, rangeShift
                sub.pairs.reserve(pairs);
                for (unsigned p = 0; p < pairs; ++p) {
                    const uint16_t left = r.u16(), right = r.u16();
                    sub.pairs.push_back({left, right, r.s16()});
                }
            } else {
                r.pos = start + length;
            }
            kern.push_back(std::move(sub));
        }
    }
}

void TtfFont::Impl::chooseCharmap(TextCharset charset) {
    // povray 3.7's search order of character map platforms (reference data
    // from POV-Ray 3.7): for ASCII strings Macintosh (1) first, then
    // Microsoft (3), Unicode (0), Microsoft again; for UTF-8 and system
    // strings Unicode (0), Microsoft (3), Macintosh (1), Microsoft. Only
    // the platform is compared, and only maps of format 0, 4 or 6 are read.
    static constexpr std::array<FT_UShort, 4> kAsciiOrder{1, 3, 0, 3};
    static constexpr std::array<FT_UShort, 4> kUnicodeOrder{0, 3, 1, 3};
    const auto& order = charset == TextCharset::Ascii ? kAsciiOrder : kUnicodeOrder;
    if (FT_IS_SFNT(face)) {
        for (const FT_UShort platform : order) {
            for (int i = 0; i < face->num_charmaps && !charmap; ++i) {
                FT_CharMap cm = face->charmaps[i];
                if (cm->platform_id != platform) continue;
                const FT_Long format = FT_Get_CMap_Format(cm);
                if (format == 0 || format == 4 || format == 6) {
                    charmap = cm;
                    charmapIsFormat4 = format == 4;
                }
            }
            if (charmap) break;
        }
    } else {
        charmap = face->charmap;
    }
    if (charmap) FT_Set_Charmap(face, charmap);
}

unsigned TtfFont::Impl::glyphIndex(char32_t code) const {
    if (!charmap) return 0;
    unsigned index = FT_Get_Char_Index(face, code);
    // Symbol fonts keep their characters at U+F000 on: povray looks there
    // for a code below 0x100 that a format 4 map does not have.
    if (index == 0 && charmapIsFormat4 && code < 0x100)
        index = FT_Get_Char_Index(face, code + 0xF000);
    return index;
}

void TtfFont::Impl::loadSimplePoints(unsigned dataGlyph, PointGlyph& g) const {
    if (FT_Load_Glyph(face, dataGlyph, kUnscaledOutline | FT_LOAD_NO_RECURSE) != 0) {
        g.contourCount = 0;
        return;
    }
    const FT_Outline& outline = face->glyph->outline;
    if (face->glyph->format != FT_GLYPH_FORMAT_OUTLINE || outline.n_contours <= 0) {
        g.contourCount = 0;
        return;
    }
    g.contourCount = outline.n_contours;
    const double em = unitsPerEm;
    for (int i = 0; i < outline.n_points; ++i) {
        const auto x = static_cast<int>(outline.points[i].x),
                   y = static_cast<int>(outline.points[i].y);
        g.xMax = static_cast<int16_t>(std::max<int>(g.xMax, x));
        g.xMin = static_cast<int16_t>(std::min<int>(g.xMin, x));
        g.yMax = static_cast<int16_t>(std::max<int>(g.yMax, y));
        g.yMin = static_cast<int16_t>(std::min<int>(g.yMin, y));
        g.points.push_back({x / em, y / em});
        g.onCurve.push_back(FT_CURVE_TAG(outline.tags[i]) == FT_CURVE_TAG_ON);
    }
    for (int c = 0; c < outline.n_contours; ++c) g.contourEnds.push_back(outline.contours[c]);
}

PointGlyph TtfFont::Impl::extract(unsigned index, char32_t code, int depth) const {
    PointGlyph g;
    g.metrics = index;
    // povray never reads a space's glyph data: no outline, an empty box.
    if (code == U' ' || index >= glyphCount || depth > 8) return g;
    // povray reads the glyph header at the glyph's offset without checking
    // its length: for an empty glyph that is the next non-empty glyph's
    // data, which it then draws.
    const uint32_t offset = loca[index];
    unsigned dataGlyph = index;
    while (dataGlyph < glyphCount && loca[dataGlyph + 1] <= offset) ++dataGlyph;
    if (dataGlyph >= glyphCount || static_cast<size_t>(offset) + 10 > glyf.size()) return g;

    TableReader r{glyf, offset};
    const int16_t contours = r.s16();
    g.xMin = r.s16();
    g.yMin = r.s16();
    g.xMax = r.s16();
    g.yMax = r.s16();
    if (contours > 0) {
        loadSimplePoints(dataGlyph, g);
        return g;
    }
    if (contours == 0) return g;

    // A composite glyph: its components' outlines, each moved and scaled,
    // one after the other (as povray 3.7 assembles them).
    uint16_t flags;
    do {
        flags = r.u16();
        const unsigned component = r.u16();
        int arg1, arg2;
        if (flags & kArgsAreWords) {
            arg1 = r.s16();
            arg2 = r.s16();
        } else {
            // povray reads byte arguments as unsigned (0..255).
            const uint16_t both = r.u16();
            arg1 = (both >> 8) & 0xFF;
            arg2 = both & 0xFF;
        }
        double xScale = 1, yScale = 1, scale01 = 0, scale10 = 0;
        if (flags & kHaveScale) {
            xScale = yScale = r.s16() / 16384.0;
        } else if (flags & kHaveXyScale) {
            xScale = r.s16() / 16384.0;
            yScale = r.s16() / 16384.0;
        } else if (flags & kHaveTwoByTwo) {
            xScale = r.s16() / 16384.0;
            scale01 = r.s16() / 16384.0;
            scale10 = r.s16() / 16384.0;
            yScale = r.s16() / 16384.0;
        }
        // povray skips components placed by matching points.
        if (!(flags & kArgsAreXyValues)) continue;
        const double xOffset = arg1 / static_cast<double>(unitsPerEm);
        const double yOffset = arg2 / static_cast<double>(unitsPerEm);
        if (flags & kUseMyMetrics) g.metrics = component;
        const PointGlyph part = extract(component, code, depth + 1);
        if (part.contourCount == 0) continue;
        const int base = static_cast<int>(g.points.size());
        for (const int end : part.contourEnds) g.contourEnds.push_back(end + base);
        g.contourCount += part.contourCount;
        for (size_t i = 0; i < part.points.size(); ++i) {
            const Point2 p = part.points[i];
            // povray's transform: note scale01 multiplies y in x.
            const Point2 q{xScale * p.x + scale01 * p.y + xOffset,
                           scale10 * p.x + yScale * p.y + yOffset};
            g.points.push_back(q);
            g.onCurve.push_back(part.onCurve[i]);
            widenTruncating(g.xMin, q.x, true);
            widenTruncating(g.xMax, q.x, false);
            widenTruncating(g.yMin, q.y, true);
            widenTruncating(g.yMax, q.y, false);
        }
    } while (flags & kMoreComponents);
    return g;
}

TtfFont::Glyph TtfFont::Impl::buildGlyph(unsigned index, char32_t code) const {
    if (glyf.empty()) return buildFreeTypeGlyph(index, code);
    const PointGlyph g = extract(index, code, 0);
    std::vector<OutlineSegment> segments;
    int first = 0;
    for (int c = 0; c < g.contourCount && c < static_cast<int>(g.contourEnds.size()); ++c) {
        const int last =
            std::min(g.contourEnds[static_cast<size_t>(c)], static_cast<int>(g.points.size()) - 1);
        contourSegments(g, first, last, segments);
        first = last + 1;
    }
    TtfFont::Glyph out;
    out.index = index;
    out.metrics = g.metrics;
    out.xMin = g.xMin;
    out.yMin = g.yMin;
    out.xMax = g.xMax;
    out.yMax = g.yMax;
    out.outline = std::make_shared<const GlyphOutline>(std::move(segments));
    return out;
}

TtfFont::Glyph TtfFont::Impl::buildFreeTypeGlyph(unsigned index, char32_t code) const {
    TtfFont::Glyph out;
    out.index = index;
    out.metrics = index;
    std::vector<OutlineSegment> segments;
    if (code != U' ' && FT_Load_Glyph(face, index, kUnscaledOutline) == 0 &&
        face->glyph->format == FT_GLYPH_FORMAT_OUTLINE) {
        FT_Outline& outline = face->glyph->outline;
        Decomposer d{1.0 / unitsPerEm, {}, {}};
        FT_Outline_Funcs funcs{};
        funcs.move_to = &Decomposer::moveTo;
        funcs.line_to = &Decomposer::lineTo;
        funcs.conic_to = &Decomposer::conicTo;
        funcs.cubic_to = &Decomposer::cubicTo;
        if (FT_Outline_Decompose(&outline, &funcs, &d) == 0) segments = std::move(d.segments);
        FT_BBox box;
        FT_Outline_Get_CBox(&outline, &box);
        if (outline.n_points > 0) {
            out.xMin = static_cast<int>(box.xMin);
            out.yMin = static_cast<int>(box.yMin);
            out.xMax = static_cast<int>(box.xMax);
            out.yMax = static_cast<int>(box.yMax);
        }
    }
    out.outline = std::make_shared<const GlyphOutline>(std::move(segments));
    return out;
}

TtfFont::TtfFont(const std::filesystem::path& file, TextCharset charset)
    : impl_(std::make_unique<Impl>()) {
    if (FT_Init_FreeType(&impl_->library) != 0) throw std::runtime_error("cannot start FreeType");
    if (FT_New_Face(impl_->library, file.c_str(), 0, &impl_->face) != 0)
        throw std::runtime_error("cannot read the font file '" + file.string() + "'");
    impl_->readTables();
    impl_->chooseCharmap(charset);
}

TtfFont::~TtfFont() = default;

int TtfFont::unitsPerEm() const {
    return impl_->unitsPerEm;
}

const TtfFont::Glyph& TtfFont::glyph(char32_t code) {
    if (const auto it = byCode_.find(code); it != byCode_.end()) return it->second;
    const unsigned index = impl_->glyphIndex(code);
    // Like povray, a glyph is built once per index: the first character
    // that reaches it decides how (a space is never read).
    if (const auto it = byIndex_.find(index); it != byIndex_.end())
        return byCode_[code] = it->second;
    const Glyph g = impl_->buildGlyph(index, code);
    byIndex_[index] = g;
    return byCode_[code] = g;
}

int TtfFont::advanceWidth(unsigned glyph) const {
    if (!impl_->hmtx.empty())
        return impl_->hmtx[std::min<size_t>(glyph, impl_->hmtx.size() - 1)].first;
    if (FT_Load_Glyph(impl_->face, glyph, kUnscaledOutline) != 0) return 0;
    return static_cast<int>(impl_->face->glyph->metrics.horiAdvance);
}

int TtfFont::leftSideBearing(unsigned glyph) const {
    if (!impl_->hmtx.empty())
        return impl_->hmtx[std::min<size_t>(glyph, impl_->hmtx.size() - 1)].second;
    if (FT_Load_Glyph(impl_->face, glyph, kUnscaledOutline) != 0) return 0;
    return static_cast<int>(impl_->face->glyph->metrics.horiBearingX);
}

TtfFont::Kerning TtfFont::kerning(unsigned leftIndex, unsigned rightMetrics) const {
    // POV-Ray 3.7's rules (reference behaviour): every subtable is read
    // with the first subtable's coverage bits; the pairs are scanned in
    // order, stopping at the first match or once the left glyph is passed;
    // the result is bounded below by minus one em (or a minimum table).
    int16_t x = 0, y = 0;
    auto minX = static_cast<int16_t>(-impl_->unitsPerEm), minY = minX;
    const auto& tables = impl_->kern;
    for (const auto& table : tables) {
        const uint16_t coverage = tables.front().coverage;
        if (!(coverage & kKernHorizontal)) continue;
        for (const auto& pair : table.pairs) {
            if (pair.left == leftIndex && pair.right == rightMetrics) {
                if (coverage & kKernMinimum) {
                    (coverage & kKernCrossStream ? minY : minX) = pair.value;
                } else if (coverage & kKernCrossStream) {
                    if (pair.value == static_cast<int16_t>(0x8000))
                        y = 0;
                    else
                        y = static_cast<int16_t>(coverage & kKernOverride ? pair.value
                                                                          : y + pair.value);
                } else {
                    x = static_cast<int16_t>(coverage & kKernOverride ? pair.value
                                                                      : x + pair.value);
                }
                break;
            }
            if (pair.left > leftIndex) break;
        }
    }
    return {std::max(x, minX), std::max(y, minY)};
}

}  // namespace frameray::scene
