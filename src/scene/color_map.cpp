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
    // povray blends in single precision: a + (b - a) * t with float
    // colours and t (measured through function { pigment { } } values).
    const float t = static_cast<float>((value - a.value) / span);
    const auto blend = [t](double from, double to) {
        const float f = static_cast<float>(from);
        return static_cast<double>(f + (static_cast<float>(to) - f) * t);
    };
    return Color(RGB(blend(a.color.rgb.r, b.color.rgb.r), blend(a.color.rgb.g, b.color.rgb.g),
                     blend(a.color.rgb.b, b.color.rgb.b)),
                 blend(a.color.filter, b.color.filter), blend(a.color.transmit, b.color.transmit));
}

}  // namespace frameray::scene
