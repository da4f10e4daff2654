// One sequence.json for a sequence rendered in shards (Shard_Index /
// Shard_Count): every shard writes sequence.shard-I-of-N.json beside the
// frames; these are merged into sequence.json, by `frameray --merge-stats
// DIR` or by the shard that finishes the sequence.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace frameray::anim {

// The merged file's text from the shards' files' texts (any order):
// "frames" every shard's rendered frames by number, "kept_frames" the
// frames kept by +C that no shard rendered, the sums of rays, tests,
// seconds and frame counts, "wall_seconds" the longest shard's,
// "shard_count", and "shards" each shard's own figures. Throws
// std::runtime_error when a text is not a shard's statistics, the shards
// disagree (scene, count), one is missing or twice, or a shard has not
// finished its frames (frames_finished < frames_planned).
std::string mergeShardStatistics(const std::vector<std::string>& shardTexts);

struct MergedStatistics {
    std::filesystem::path file;  // DIR/sequence.json
    size_t shards = 0, framesRendered = 0, framesKept = 0;
};

// Reads DIR/sequence.shard-*-of-N.json (one N), writes DIR/sequence.json
// atomically. Throws std::runtime_error saying what is missing or wrong.
MergedStatistics mergeShardStatisticsIn(const std::filesystem::path& dir);

}  // namespace frameray::anim
