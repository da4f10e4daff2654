// Colour maps: a pattern value in [0, 1] picks a colour by linear
// interpolation between sorted entries (seed 003 §5.4.1.3.2).
#pragma once

#include <vector>

#include "util/color.h"

namespace frameray::scene {

class ColorMap {
  public:
    struct Entry {
        double value;
        Color color;
    };
    static constexpr std::size_t kMaxEntries = 256;  // POV-Ray's limit

    ColorMap() = default;
    // Entries are normally sorted by value; equal values make a sharp step.
    // Unsorted ones are looked up as povray does (measured): the first
    // entry, in written order, above the value and the one before it.
    explicit ColorMap(std::vector<Entry> entries) : entries_(std::move(entries)) {}

    // POV-Ray's map for a colour-mapped pattern without one: black to white.
    static ColorMap grayscale();

    // Below the first entry the first colour, above the last the last one;
    // all five channels are interpolated.
    Color at(double value) const;

    const std::vector<Entry>& entries() const { return entries_; }
    bool empty() const { return entries_.empty(); }

  private:
    std::vector<Entry> entries_;
};

}  // namespace frameray::scene
