// How many frames fit in memory at once. The scheduler renders the first
// frame alone, measures how much the process grew meanwhile (its peak
// resident size over the size before), and then keeps no more frames in
// flight than the memory available (the machine's, or the cgroup's under
// Slurm / Kubernetes limits) can hold.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace frameray::anim {

// The process's resident size now and its peak so far, in bytes.
std::uint64_t residentBytes();
std::uint64_t peakResidentBytes();

// Bytes this process may still take: MemAvailable, lowered to what the
// cgroup's limit leaves (v2 memory.max, v1 limit_in_bytes). 0: unknown.
std::uint64_t availableBytes();

// Parses /proc/meminfo text: MemAvailable in bytes.
std::optional<std::uint64_t> memAvailableFrom(const std::string& meminfo);
// The room a cgroup (v2 then v1) under `root` leaves: limit - usage.
std::optional<std::uint64_t> cgroupRoom(const std::filesystem::path& root);

// Frames in flight: `wanted` (the option, or the default from the core
// count), lowered so that `frames * perFrame` stays within 3/4 of
// `available`; at least 1. An unknown (0) estimate or budget leaves it.
std::size_t framesWithin(std::size_t wanted, std::uint64_t perFrame, std::uint64_t available);

}  // namespace frameray::anim
