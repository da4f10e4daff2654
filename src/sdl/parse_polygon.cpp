// polygon { N, <P1>, <P2>, ... <PN> [modifiers] } (povray 3.7): the points,
// 2-D vectors taken as <x, y, 0>, form closed loops: a loop ends where a
// point repeats the loop's first one, and the next point starts another.
// Loops inside others are holes (even-odd rule). A last loop left open is
// closed with povray's warning; fewer than three points are refused with
// its error (both measured).
#include <cmath>

#include "scene/polygon.h"
#include "sdl/builders.h"

namespace frameray::sdl {

std::shared_ptr<const scene::Shape> parsePolygon(BuildContext& c, const Token& kind) {
    Reader& r = c.reader;
    const Token countAt = r.peek();
    const double count = r.parseFloat();
    if (count < 3) r.fail(countAt, "Polygon needs at least three points.");
    std::vector<std::vector<Vec3>> loops;
    std::vector<Vec3> loop;
    for (int i = 0; i < static_cast<int>(count); ++i) {
        r.accept(Sym::Comma);
        const Vec3 p = r.parseVec3();
        if (loop.empty()) {
            loop.push_back(p);
            continue;
        }
        const Vec3 d = p - loop.front();
        if (loop.size() > 1 && std::fabs(d.x) < 1e-10 && std::fabs(d.y) < 1e-10 &&
            std::fabs(d.z) < 1e-10) {
            loops.push_back(std::move(loop));
            loop.clear();
            continue;
        }
        loop.push_back(p);
    }
    if (!loop.empty()) {
        r.warn(kind, "Polygon not closed. Closing it.");
        loops.push_back(std::move(loop));
    }
    return std::make_shared<scene::Polygon>(loops);
}

}  // namespace frameray::sdl
