#include "anim/memory_budget.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

namespace frameray::anim {

namespace fs = std::filesystem;

namespace {

std::optional<std::string> readText(const fs::path& path) {
    std::ifstream in(path);
    if (!in) return std::nullopt;
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// A number file of the cgroup interface; nullopt for "max" or junk.
std::optional<std::uint64_t> readNumber(const fs::path& path) {
    const auto text = readText(path);
    if (!text) return std::nullopt;
    try {
        size_t used = 0;
        const unsigned long long v = std::stoull(*text, &used);
        return static_cast<std::uint64_t>(v);
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

}  // namespace

std::uint64_t residentBytes() {
    std::ifstream in("/proc/self/statm");
    std::uint64_t size = 0, resident = 0;
    if (!(in >> size >> resident)) return 0;
    return resident * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
}

std::uint64_t peakResidentBytes() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<std::uint64_t>(u.ru_maxrss) * 1024;  // Linux reports KiB
}

std::optional<std::uint64_t> memAvailableFrom(const std::string& meminfo) {
    std::istringstream in(meminfo);
    std::string key;
    std::uint64_t kib = 0;
    std::string unit;
    while (in >> key >> kib) {
        std::getline(in, unit);
        if (key == "MemAvailable:") return kib * 1024;
    }
    return std::nullopt;
}

std::optional<std::uint64_t> cgroupRoom(const fs::path& root) {
    // cgroup v2: the process's group is the root of its namespace in a
    // container, and under Slurm / systemd /proc/self/cgroup names it.
    std::optional<std::uint64_t> limit = readNumber(root / "memory.max");
    std::optional<std::uint64_t> usage = readNumber(root / "memory.current");
    if (!limit) {
        limit = readNumber(root / "memory/memory.limit_in_bytes");
        usage = readNumber(root / "memory/memory.usage_in_bytes");
    }
    // v1 writes a huge number for "no limit".
    if (!limit || *limit >= (std::uint64_t{1} << 60)) return std::nullopt;
    const std::uint64_t used = usage.value_or(0);
    return *limit > used ? *limit - used : 0;
}

std::uint64_t availableBytes() {
    std::optional<std::uint64_t> room;
    if (const auto meminfo = readText("/proc/meminfo")) room = memAvailableFrom(*meminfo);
    // The process's own cgroup (v2: one line "0::/path").
    std::optional<std::uint64_t> group;
    if (const auto self = readText("/proc/self/cgroup")) {
        std::istringstream in(*self);
        std::string line;
        while (std::getline(in, line))
            if (line.rfind("0::", 0) == 0)
                group = cgroupRoom(fs::path("/sys/fs/cgroup") / line.substr(4));
    }
    if (!group) group = cgroupRoom("/sys/fs/cgroup");
    if (group) room = room ? std::min(*room, *group) : *group;
    return room.value_or(0);
}

std::size_t framesWithin(std::size_t wanted, std::uint64_t perFrame, std::uint64_t available) {
    wanted = std::max<std::size_t>(wanted, 1);
    if (perFrame == 0 || available == 0) return wanted;
    const std::uint64_t fit = available / 4 * 3 / perFrame;
    return static_cast<std::size_t>(std::clamp<std::uint64_t>(fit, 1, wanted));
}

}  // namespace frameray::anim
