#include "anim/shard_statistics.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "util/durable_file.h"
#include "util/json.h"

namespace frameray::anim {

namespace fs = std::filesystem;
using util::JsonValue;

namespace {

// The whole-sequence keys the merge computes; the rest of a shard's
// top-level numbers are that shard's own figures.
const std::set<std::string> mergedKeys{"scene", "frames", "kept_frames", "rays",
                                       "intersection_tests"};

std::int64_t integerMember(const JsonValue& v, const char* key) {
    const JsonValue* m = v.find(key);
    const auto n = m ? m->asInteger() : std::nullopt;
    if (!n) throw std::runtime_error(fmt::format("no integer \"{}\"", key));
    return *n;
}

double numberMember(const JsonValue& v, const char* key) {
    const JsonValue* m = v.find(key);
    const auto d = m ? m->asDouble() : std::nullopt;
    if (!d) throw std::runtime_error(fmt::format("no number \"{}\"", key));
    return *d;
}

const JsonValue& arrayMember(const JsonValue& v, const char* key) {
    const JsonValue* m = v.find(key);
    if (!m || m->kind != JsonValue::Kind::Array)
        throw std::runtime_error(fmt::format("no array \"{}\"", key));
    return *m;
}

// Adds up objects of counts ({"camera": 10, ...}) key by key, keeping the
// first object's key order and appending keys seen later.
JsonValue sumCounts(const std::vector<const JsonValue*>& objects) {
    std::vector<std::string> order;
    std::map<std::string, std::uint64_t> sums;
    for (const JsonValue* o : objects) {
        if (!o || o->kind != JsonValue::Kind::Object) continue;
        for (const auto& [key, value] : o->members) {
            const auto n = value.asInteger();
            if (!n || *n < 0) throw std::runtime_error(fmt::format("\"{}\" is not a count", key));
            if (!sums.contains(key)) order.push_back(key);
            sums[key] += static_cast<std::uint64_t>(*n);
        }
    }
    JsonValue out = JsonValue::object();
    for (const std::string& key : order)
        out.members.emplace_back(key, JsonValue::number(std::to_string(sums[key])));
    return out;
}

JsonValue seconds(double s) {
    return JsonValue::number(fmt::format("{:.6f}", s));
}

std::string frameList(const std::vector<const JsonValue*>& frames) {
    std::string out;
    for (const JsonValue* f : frames) {
        if (!out.empty()) out += ",\n";
        out += "    " + util::writeJsonInline(*f);
    }
    return out;
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(fmt::format("cannot read '{}'", path.string()));
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

std::string mergeShardStatistics(const std::vector<std::string>& shardTexts) {
    if (shardTexts.empty()) throw std::runtime_error("no shard statistics to merge");
    std::vector<JsonValue> shards;
    for (const std::string& text : shardTexts) shards.push_back(util::parseJson(text));
    std::int64_t shardCount = 0;
    std::string scene;
    std::map<std::int64_t, const JsonValue*> byIndex;
    for (const JsonValue& s : shards) {
        const std::int64_t index = integerMember(s, "shard_index");
        const std::int64_t n = integerMember(s, "shard_count");
        const JsonValue* name = s.find("scene");
        if (!name || name->kind != JsonValue::Kind::String)
            throw std::runtime_error("no \"scene\": not a sequence statistics file");
        if (byIndex.empty()) {
            shardCount = n;
            scene = name->text;
        } else if (n != shardCount || name->text != scene) {
            throw std::runtime_error(
                fmt::format("shard files of different runs: scene '{}' in {} shards and '{}' in {}",
                            scene, shardCount, name->text, n));
        }
        if (index < 0 || index >= n) throw std::runtime_error("a shard_index out of range");
        if (!byIndex.emplace(index, &s).second)
            throw std::runtime_error(fmt::format("shard {} given twice", index));
        const std::int64_t finished = integerMember(s, "frames_finished");
        const std::int64_t planned = integerMember(s, "frames_planned");
        if (finished < planned)
            throw std::runtime_error(fmt::format("shard {} of {} has finished {} of its {} frames",
                                                 index, n, finished, planned));
    }
    for (std::int64_t i = 0; i < shardCount; ++i)
        if (!byIndex.contains(i))
            throw std::runtime_error(
                fmt::format("no statistics of shard {} of {} (sequence.shard-{}-of-{}.json)", i,
                            shardCount, i, shardCount));

    // Frames by number: each shard renders its own, so a number met twice
    // would mean files of different runs; the first shard's record stands.
    std::map<std::int64_t, const JsonValue*> rendered, kept;
    std::vector<const JsonValue*> rays, tests, shardFigures;
    double parse = 0, prepare = 0, render = 0, write = 0, cpu = 0, wall = 0;
    std::uint64_t finished = 0, planned = 0;
    JsonValue perShard = JsonValue::array();
    for (const auto& [index, s] : byIndex) {
        for (const JsonValue& f : arrayMember(*s, "frames").items)
            rendered.emplace(integerMember(f, "number"), &f);
        for (const JsonValue& f : arrayMember(*s, "kept_frames").items)
            kept.emplace(integerMember(f, "number"), &f);
        rays.push_back(s->find("rays"));
        tests.push_back(s->find("intersection_tests"));
        parse += numberMember(*s, "parse_seconds");
        prepare += numberMember(*s, "prepare_seconds");
        render += numberMember(*s, "render_seconds");
        write += numberMember(*s, "write_seconds");
        cpu += numberMember(*s, "cpu_seconds");
        wall = std::max(wall, numberMember(*s, "wall_seconds"));
        finished += static_cast<std::uint64_t>(integerMember(*s, "frames_finished"));
        planned += static_cast<std::uint64_t>(integerMember(*s, "frames_planned"));
        JsonValue own = JsonValue::object();
        for (const auto& [key, value] : s->members)
            if (!mergedKeys.contains(key)) own.members.emplace_back(key, value);
        perShard.items.push_back(std::move(own));
    }
    std::vector<const JsonValue*> frames, keptOnly;
    for (const auto& [number, f] : rendered) frames.push_back(f);
    for (const auto& [number, f] : kept)
        if (!rendered.contains(number)) keptOnly.push_back(f);

    std::string shardLines;
    for (const JsonValue& own : perShard.items) {
        if (!shardLines.empty()) shardLines += ",\n";
        shardLines += "    " + util::writeJsonInline(own);
    }
    return fmt::format(
        "{{\n  \"scene\": {},\n  \"frames\": [\n{}\n  ],\n  \"kept_frames\": [\n{}\n  ],\n"
        "  \"rays\": {},\n  \"intersection_tests\": {},\n  \"frames_rendered\": {},\n"
        "  \"frames_kept\": {},\n  \"frames_finished\": {},\n  \"frames_planned\": {},\n"
        "  \"shard_count\": {},\n  \"parse_seconds\": {},\n  \"prepare_seconds\": {},\n"
        "  \"render_seconds\": {},\n  \"write_seconds\": {},\n  \"wall_seconds\": {},\n"
        "  \"cpu_seconds\": {},\n  \"shards\": [\n{}\n  ]\n}}\n",
        util::writeJsonInline(JsonValue::string(scene)), frameList(frames), frameList(keptOnly),
        util::writeJsonInline(sumCounts(rays)), util::writeJsonInline(sumCounts(tests)),
        frames.size(), keptOnly.size(), finished, planned, shardCount,
        util::writeJsonInline(seconds(parse)), util::writeJsonInline(seconds(prepare)),
        util::writeJsonInline(seconds(render)), util::writeJsonInline(seconds(write)),
        util::writeJsonInline(seconds(wall)), util::writeJsonInline(seconds(cpu)), shardLines);
}

MergedStatistics mergeShardStatisticsIn(const fs::path& dir) {
    // sequence.shard-I-of-N.json, grouped by N.
    std::map<int, std::vector<fs::path>> byCount;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        const std::string prefix = "sequence.shard-", suffix = ".json";
        if (!name.starts_with(prefix) || !name.ends_with(suffix)) continue;
        const std::string tag =
            name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
        const size_t of = tag.find("-of-");
        if (of == std::string::npos) continue;
        int count = 0;
        const char* first = tag.data() + of + 4;
        const char* last = tag.data() + tag.size();
        if (auto [end, e] = std::from_chars(first, last, count); e != std::errc() || end != last)
            continue;
        byCount[count].push_back(entry.path());
    }
    if (ec)
        throw std::runtime_error(
            fmt::format("cannot read the folder '{}': {}", dir.string(), ec.message()));
    if (byCount.empty())
        throw std::runtime_error(
            fmt::format("no shard statistics (sequence.shard-I-of-N.json) in '{}'", dir.string()));
    if (byCount.size() > 1) {
        std::string counts;
        for (const auto& [n, files] : byCount)
            counts += fmt::format("{}{}", counts.empty() ? "" : ", ", n);
        throw std::runtime_error(fmt::format(
            "shard statistics of runs in {} different shard counts ({}) in '{}'; remove the old "
            "ones",
            byCount.size(), counts, dir.string()));
    }
    std::vector<fs::path> files = byCount.begin()->second;
    std::sort(files.begin(), files.end());
    std::vector<std::string> texts;
    for (const fs::path& f : files) texts.push_back(readFile(f));
    std::string merged;
    try {
        merged = mergeShardStatistics(texts);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(fmt::format("'{}': {}", dir.string(), e.what()));
    }
    MergedStatistics result;
    result.file = dir / "sequence.json";
    util::replaceFileDurably(result.file, merged);
    const JsonValue summary = util::parseJson(merged);
    result.shards = files.size();
    result.framesRendered = summary.find("frames")->items.size();
    result.framesKept = summary.find("kept_frames")->items.size();
    return result;
}

}  // namespace frameray::anim
