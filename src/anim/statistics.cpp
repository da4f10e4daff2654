#include "anim/statistics.h"

#include <fmt/format.h>

#include <map>

#include "anim/journal.h"
#include "util/json.h"

namespace frameray::anim {

namespace {

std::string jsonRays(const render::RayCounts& r) {
    return fmt::format(
        "{{\"camera\": {}, \"shadow\": {}, \"reflection\": {}, \"refraction\": {}, "
        "\"transmission\": {}, \"media_samples\": {}, \"radiosity\": {}}}",
        r.camera, r.shadow, r.reflection, r.refraction, r.transmission, r.mediaSamples,
        r.radiosity);
}

std::string jsonTests(const render::ShapeTestCounts& tests) {
    std::string out = "{";
    for (const auto& [kind, n] : tests) {
        if (out.size() > 1) out += ", ";
        out += fmt::format("{}: {}", jsonString(kind), n);
    }
    return out + "}";
}

// The photon maps of a frame: photons shot, kept on surfaces and left in
// media, the bytes the maps hold, the gather radii and spacing used, and
// whether the maps were loaded from a file (load_file) instead of shot.
std::string jsonPhotons(const std::optional<render::PhotonStats>& p) {
    if (!p) return "";
    return fmt::format(
        ", \"photons\": {{\"shot\": {}, \"stored\": {}, \"media_stored\": {}, "
        "\"memory_bytes\": {}, \"gather_radius\": {:.6g}, \"media_gather_radius\": {:.6g}, "
        "\"spacing\": {:.6g}, \"loaded\": {}}}",
        p->shot, p->stored, p->mediaStored, p->memoryBytes, p->gatherRadius, p->mediaGatherRadius,
        p->spacing, p->loaded);
}

}  // namespace

std::uint64_t totalRays(const render::RayCounts& r) {
    return r.camera + r.shadow + r.reflection + r.refraction + r.transmission + r.radiosity;
}

std::string jsonString(const std::string& text) {
    return util::jsonQuoted(text);
}

render::ShapeTestCounts sumShapeTests(const std::vector<FrameRecord>& records) {
    std::map<std::string, std::uint64_t> sum;
    for (const FrameRecord& r : records)
        for (const auto& [kind, n] : r.shapeTests) sum[kind] += n;
    return {sum.begin(), sum.end()};
}

std::string sequenceJson(const RunFigures& run, const std::vector<FrameRecord>& records,
                         const std::vector<KeptFrame>& kept) {
    render::RayCounts total;
    double parse = 0, prepare = 0, render = 0, write = 0;
    std::string frames;
    for (const FrameRecord& r : records) {
        total += r.rays;
        parse += r.parseSeconds;
        prepare += r.prepareSeconds;
        render += r.renderSeconds;
        write += r.writeSeconds;
        if (!frames.empty()) frames += ",\n";
        // The flat keys came first (issue 4's slice); "stats" groups what
        // was measured of the frame.
        frames += fmt::format(
            "    {{\"number\": {}, \"clock\": {}, \"file\": {}, \"rays\": {}, "
            "\"parse_seconds\": {:.6f}, \"prepare_seconds\": {:.6f}, \"render_seconds\": {:.6f}, "
            "\"write_seconds\": {:.6f},\n     \"stats\": {{\"rays\": {}, \"intersection_tests\": "
            "{}, "
            "\"parse_seconds\": {:.6f}, \"prepare_seconds\": {:.6f}, \"render_seconds\": {:.6f}, "
            "\"write_seconds\": {:.6f}, \"commit_seconds\": {:.6f}{}}}}}",
            r.number, clockText(r.clock), jsonString(r.file), jsonRays(r.rays), r.parseSeconds,
            r.prepareSeconds, r.prepareSeconds + r.renderSeconds, r.writeSeconds, jsonRays(r.rays),
            jsonTests(r.shapeTests), r.parseSeconds, r.prepareSeconds,
            r.prepareSeconds + r.renderSeconds, r.writeSeconds, r.commitSeconds,
            jsonPhotons(r.photons));
    }
    std::string keptList;
    for (const KeptFrame& k : kept) {
        if (!keptList.empty()) keptList += ",\n";
        keptList += fmt::format("    {{\"number\": {}, \"clock\": {}, \"file\": {}}}", k.number,
                                clockText(k.clock), jsonString(k.file));
    }
    const double utilisation =
        run.wallSeconds > 0 && run.workThreads > 0
            ? run.cpuSeconds / (run.wallSeconds * static_cast<double>(run.workThreads))
            : 0;
    return fmt::format(
        "{{\n  \"scene\": {},\n  \"frames\": [\n{}\n  ],\n  \"kept_frames\": [\n{}\n  ],\n  "
        "\"rays\": {},\n"
        "  \"intersection_tests\": {},\n  \"frames_rendered\": {},\n  \"frames_kept\": {},\n"
        "  \"frames_finished\": {},\n  \"frames_planned\": {},\n  \"shard_index\": {},\n  "
        "\"shard_count\": {},\n"
        "  \"parse_seconds\": {:.6f},\n  \"prepare_seconds\": {:.6f},\n  \"render_seconds\": "
        "{:.6f},\n"
        "  \"write_seconds\": {:.6f},\n  \"wall_seconds\": {:.6f},\n  \"cpu_seconds\": {:.6f},\n"
        "  \"work_threads\": {},\n  \"frames_in_flight\": {},\n  \"frame_memory_estimate_bytes\": "
        "{},\n"
        "  \"memory_budget_bytes\": {},\n  \"cpu_utilisation\": {:.4f}\n}}\n",
        jsonString(run.scene), frames, keptList, jsonRays(total), jsonTests(sumShapeTests(records)),
        records.size(), kept.size(), run.framesFinished, run.framesPlanned, run.shardIndex,
        run.shardCount, parse, prepare, prepare + render, write, run.wallSeconds, run.cpuSeconds,
        run.workThreads, run.framesInFlight, run.frameMemoryEstimate, run.memoryBudget,
        utilisation);
}

std::string summaryTable(const RunFigures& run, const std::vector<FrameRecord>& records,
                         size_t keptFrames) {
    render::RayCounts rays;
    for (const FrameRecord& r : records) rays += r.rays;
    const std::uint64_t all = totalRays(rays);
    const double perSecond = run.wallSeconds > 0 ? static_cast<double>(all) / run.wallSeconds : 0;
    const double utilisation =
        run.wallSeconds > 0 && run.workThreads > 0
            ? 100.0 * run.cpuSeconds / (run.wallSeconds * static_cast<double>(run.workThreads))
            : 0;
    std::string frames = fmt::format("{} rendered", records.size());
    if (keptFrames) frames += fmt::format(", {} kept (+C)", keptFrames);
    frames += fmt::format(" of {}", run.framesPlanned);
    if (run.shardCount > 1)
        frames += fmt::format(" (shard {} of {})", run.shardIndex, run.shardCount);
    std::string out = "frameray summary\n";
    auto row = [&out](const char* name, const std::string& value) {
        out += fmt::format("  {:<9} {}\n", name, value);
    };
    row("frames", frames);
    row("wall", fmt::format("{:.2f} s", run.wallSeconds));
    row("CPU", fmt::format("{:.2f} s ({:.0f}% of {} threads, {} frames in flight)", run.cpuSeconds,
                           utilisation, run.workThreads, run.framesInFlight));
    row("rays",
        fmt::format("{} (camera {}, shadow {}, reflection {}, refraction {}, transmission {}, "
                    "radiosity {})",
                    all, rays.camera, rays.shadow, rays.reflection, rays.refraction,
                    rays.transmission, rays.radiosity));
    row("rays/s", fmt::format("{:.0f}", perSecond));
    return out;
}

}  // namespace frameray::anim
