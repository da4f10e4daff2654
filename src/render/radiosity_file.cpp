#include "render/radiosity_file.h"

#include <fmt/format.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace frameray::render {

namespace {

// Format 3 adds each sample's quality; format 2 files (without it) are
// still read, their samples of quality 1.
constexpr const char* kHeader = "frameray radiosity cache 3";
constexpr const char* kHeader2 = "frameray radiosity cache 2";

}  // namespace

void writeRadiosityFile(const std::filesystem::path& file,
                        std::span<const RadiositySample> samples) {
    std::string text = fmt::format("{}\n", kHeader);
    // Shortest round-trip numbers: a file read back gives the same samples
    // bit for bit, so a render started from it is deterministic.
    for (const RadiositySample& s : samples)
        text += fmt::format("{} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {}\n", s.depth, s.point.x,
                            s.point.y, s.point.z, s.normal.x, s.normal.y, s.normal.z,
                            s.irradiance.r, s.irradiance.g, s.irradiance.b, s.radius, s.nearest,
                            s.toNearest.x, s.toNearest.y, s.toNearest.z, s.quality);
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out)
        throw std::runtime_error(
            fmt::format("cannot write the radiosity cache file '{}'", file.string()));
}

std::vector<RadiositySample> readRadiosityFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in)
        throw std::runtime_error(
            fmt::format("cannot open the radiosity cache file '{}'", file.string()));
    std::string line;
    if (!std::getline(in, line) || (line != kHeader && line != kHeader2))
        throw std::runtime_error(
            fmt::format("'{}' is not a frameray radiosity cache file (frameray reads only the "
                        "files it writes with Radiosity_To_File, not povray's)",
                        file.string()));
    const bool withQuality = line == kHeader;
    std::vector<RadiositySample> samples;
    for (int number = 2; std::getline(in, line); ++number) {
        if (line.empty()) continue;
        std::istringstream fields(line);
        fields.imbue(std::locale::classic());
        RadiositySample s;
        fields >> s.depth >> s.point.x >> s.point.y >> s.point.z >> s.normal.x >> s.normal.y >>
            s.normal.z >> s.irradiance.r >> s.irradiance.g >> s.irradiance.b >> s.radius >>
            s.nearest >> s.toNearest.x >> s.toNearest.y >> s.toNearest.z;
        if (withQuality) fields >> s.quality;
        std::string rest;
        if (!fields || (fields >> rest) || s.depth < 0 || !(s.radius > 0) || !(s.quality > 0) ||
            s.quality > 1)
            throw std::runtime_error(fmt::format(
                "{}:{}: not a radiosity sample (depth, point, normal, irradiance, radius, nearest "
                "surface{})",
                file.string(), number, withQuality ? ", quality" : ""));
        samples.push_back(s);
    }
    return samples;
}

}  // namespace frameray::render
