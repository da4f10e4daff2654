// What a run measured, per frame and in total: sequence.json (machine
// readable, beside the frames) and the summary table printed at the end.
// Pure formatting: the frame loop gathers the figures.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "render/photons.h"
#include "render/tracer.h"
#include "render/world.h"

namespace frameray::anim {

// A frame rendered and written by this run.
struct FrameRecord {
    int number = 0;
    double clock = 0;
    std::string file;
    render::RayCounts rays;
    render::ShapeTestCounts shapeTests;  // intersection tests by kind of object
    double parseSeconds = 0, prepareSeconds = 0, renderSeconds = 0, writeSeconds = 0;
    // The part of writeSeconds spent in the serial stage (rename, journal).
    double commitSeconds = 0;
    std::optional<render::PhotonStats> photons;  // when the scene shot photons
};

// A frame an earlier run finished, kept by Continue_Trace (+C).
struct KeptFrame {
    int number = 0;
    double clock = 0;
    std::string file;
};

struct RunFigures {
    std::string scene;
    size_t framesPlanned = 0;   // in this run (this shard)
    size_t framesFinished = 0;  // rendered + kept
    size_t workThreads = 1;
    size_t framesInFlight = 1;
    double wallSeconds = 0;
    double cpuSeconds = 0;
    std::uint64_t frameMemoryEstimate = 0;  // bytes; 0: not measured
    std::uint64_t memoryBudget = 0;         // bytes; 0: none known
    int shardIndex = 0, shardCount = 1;
};

// The intersection tests of several frames added up, by kind.
render::ShapeTestCounts sumShapeTests(const std::vector<FrameRecord>& records);

// sequence.json's text: "frames" (number, clock, file, rays, stats
// {rays, intersection_tests, parse/prepare/render/write seconds}), the
// frames kept by +C, and the sums.
std::string sequenceJson(const RunFigures& run, const std::vector<FrameRecord>& records,
                         const std::vector<KeptFrame>& kept);

// The table printed at the end of an animation: frames, wall, CPU, rays,
// rays per second.
std::string summaryTable(const RunFigures& run, const std::vector<FrameRecord>& records,
                         size_t keptFrames);

std::string jsonString(const std::string& text);

// Every ray a frame traced (media sample points are not rays).
std::uint64_t totalRays(const render::RayCounts& rays);

}  // namespace frameray::anim
