// A font for the text object, read through FreeType when the scene is
// parsed. It answers what POV-Ray 3.7's own TrueType reader answers, so
// text lays out and looks the same:
//   - which glyph a character maps to: the character maps are searched in
//     povray's platform order for the string charset, and only the map
//     formats povray reads (0, 4 and 6) are used;
//   - each glyph's outline in em units, built from the TrueType points as
//     povray walks them (quadratic curves, composite glyphs assembled by
//     povray's rules), and povray's glyph box and metrics glyph;
//   - the hmtx advance and left side bearing, and the kern table pairs.
// Fonts without TrueType outlines (CFF) are read through FreeType's own
// outlines, with cubic curves; povray 3.7 cannot read those at all.
//
// A TtfFont belongs to one interpreter (one frame's parse): it caches the
// glyphs it has built and is not thread-safe. The outlines it hands out
// are immutable and may be shared freely.
#pragma once

#include <filesystem>
#include <map>
#include <memory>

#include "scene/glyph_outline.h"

namespace frameray::scene {

// How a string's bytes become character codes (global_settings charset).
enum class TextCharset { Ascii, Utf8, System };

class TtfFont {
  public:
    // Reads the font file. `charset` picks the character map, as povray
    // does when it first opens a font. Throws std::runtime_error when the
    // file is not a font FreeType can read.
    TtfFont(const std::filesystem::path& file, TextCharset charset);
    ~TtfFont();
    TtfFont(const TtfFont&) = delete;
    TtfFont& operator=(const TtfFont&) = delete;

    struct Glyph {
        unsigned index = 0;    // glyph index from the character map (0: not in the font)
        unsigned metrics = 0;  // glyph whose hmtx entry spaces this one
        // povray's box of the glyph in font units: the glyph header, widened
        // by the points read (its bounding box and the first glyph's shift).
        int xMin = 0, yMin = 0, xMax = 0, yMax = 0;
        std::shared_ptr<const GlyphOutline> outline;  // never null; empty for a space
    };
    // The glyph for a character code; cached, so repeated characters share
    // one outline.
    const Glyph& glyph(char32_t code);

    int unitsPerEm() const;
    // hmtx advance width and left side bearing of a glyph, in font units.
    int advanceWidth(unsigned glyph) const;
    int leftSideBearing(unsigned glyph) const;

    // The kerning POV-Ray applies between a glyph and the next one (given
    // by its metrics glyph), in font units: horizontal and cross-stream.
    struct Kerning {
        int x = 0, y = 0;
    };
    Kerning kerning(unsigned leftIndex, unsigned rightMetrics) const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::map<char32_t, Glyph> byCode_;
    std::map<unsigned, Glyph> byIndex_;
};

}  // namespace frameray::scene
