#include "image/ppm_writer.h"

#include <fmt/format.h>

#include <cmath>
#include <cstddef>

namespace frameray::image {

std::vector<unsigned char> encodePpm(int width, int height, int channels, int bits,
                                     const std::vector<double>& levels) {
    const bool colour = channels >= 3;
    const int written = colour ? 3 : 1;
    const int maxValue = (1 << bits) - 1;
    const std::string header =
        fmt::format("{}\n{} {}\n{}\n", colour ? "P6" : "P5", width, height, maxValue);
    const std::size_t bytesPerSample = maxValue > 255 ? 2 : 1;
    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    std::vector<unsigned char> out(header.begin(), header.end());
    out.reserve(out.size() + pixels * written * bytesPerSample);
    for (std::size_t p = 0; p < pixels; ++p)
        for (int c = 0; c < written; ++c) {
            const auto v = static_cast<unsigned>(levels[p * channels + c]);
            if (bytesPerSample == 2) out.push_back(static_cast<unsigned char>(v >> 8));
            out.push_back(static_cast<unsigned char>(v & 0xff));
        }
    return out;
}

}  // namespace frameray::image
