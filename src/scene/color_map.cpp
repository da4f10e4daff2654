#include "scene/color_map.h"

namespace frameray::scene {

ColorMap ColorMap::grayscale() {
    return ColorMap({{0.0, Color(RGB(0.0))}, {1.0, Color(RGB(1.0))}});
}

Color ColorMap::at(double value) const {
    if (entries_.empty()) return Color();
    if (value <= entries_.front().value) return entries_.front().color;
    // The first entry above the value; the one before it is at or below.
    std::size_t hi = 1;
    while (hi < entries_.size() && entries_[hi].value <= value) ++hi;
    if (hi == entries_.size()) return entries_.back().color;
    const Entry& a = entries_[hi - 1];
    const Entry& b = entries_[hi];
    const double span = b.value - a.value;
    if (span <= 0) return b.color;
    const double t = (value - a.value) / span, s = 1.0 - t;
    return Color(a.color.rgb * s + b.color.rgb * t, a.color.filter * s + b.color.filter * t,
                 a.color.transmit * s + b.color.transmit * t);
}

}  // namespace frameray::scene
