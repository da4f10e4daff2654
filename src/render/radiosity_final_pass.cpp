#include "render/radiosity_final_pass.h"

#include <algorithm>

namespace frameray::render {

namespace {

// A final-pass sample and how far from its point a lookup may use it: its
// radius times the widest bound a lookup of its depth uses (the error
// bound, widened by at most 1/4 for faint rays, times the depth's factor).
struct Reach {
    Vec3 point;
    double reach;
};

bool mayReach(const std::vector<Reach>& placed, const RadiosityTask::Box& box) {
    if (box.empty) return false;
    for (const Reach& r : placed) {
        const double dx = std::max({box.lo.x - r.point.x, 0.0, r.point.x - box.hi.x});
        const double dy = std::max({box.lo.y - r.point.y, 0.0, r.point.y - box.hi.y});
        const double dz = std::max({box.lo.z - r.point.z, 0.0, r.point.z - box.hi.z});
        if (dx * dx + dy * dy + dz * dz <= r.reach * r.reach) return true;
    }
    return false;
}

}  // namespace

RadiosityCounts settleFinalPass(Radiosity& radiosity,
                                std::vector<std::optional<RadiosityTask>>& tasks,
                                const std::function<void(int, RadiosityTask&)>& rerender) {
    const scene::RadiositySettings& set = radiosity.settings();
    std::vector<Reach> placed;
    const auto place = [&](const RadiositySample& s) {
        const double widest = (set.errorBound + 0.25) * radiosity.depth(s.depth).boundFactor;
        placed.push_back({s.point, s.radius * widest * (1 + 1e-9)});
    };
    std::vector<size_t> cursor;  // where the pool stands for the next block
    const auto turned = [&] {
        return std::any_of(cursor.begin(), cursor.end(), [](size_t c) { return c != 0; });
    };
    RadiosityCounts counts;
    for (size_t index = 0; index < tasks.size(); ++index) {
        RadiosityTask& first = *tasks[index];
        if ((first.gathered() && turned()) || mayReach(placed, first.lookups())) {
            RadiosityTask again(radiosity, false, true);
            again.setCursor(cursor);
            const size_t before = radiosity.samples().size();
            rerender(static_cast<int>(index), again);
            for (size_t i = before; i < radiosity.samples().size(); ++i)
                place(radiosity.samples()[i]);
            cursor = again.cursor();
            counts += again.counts;
        } else {
            for (const RadiositySample& s : first.takeOwn()) {
                radiosity.add(s);
                place(s);
            }
            if (first.gathered()) cursor = first.cursor();
            counts += first.counts;
        }
        tasks[index].reset();
    }
    return counts;
}

}  // namespace frameray::render
