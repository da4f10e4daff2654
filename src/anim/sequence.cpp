#include "anim/sequence.h"

#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <cmath>

#include "options/options.h"

namespace frameray::anim {

namespace fs = std::filesystem;

image::FileType fileTypeFor(char letter) {
    switch (letter) {
        case 'P':
            return image::FileType::PPM;
        case 'T':
            return image::FileType::TGA;
        case 'C':
            return image::FileType::TGA_RLE;
        case 'E':
            return image::FileType::EXR;
        case 'H':
            return image::FileType::HDR;
        case 'J':
            return image::FileType::JPEG;
        case 'B':
            return image::FileType::BMP;
        default:
            return image::FileType::PNG;
    }
}

namespace {

// An output name's parts: folder, base name (without the type's
// extension) and extension.
struct NameParts {
    std::string folder, base, extension;
};

NameParts nameParts(const options::RenderOptions& o, image::FileType type) {
    NameParts n;
    n.extension = image::extensionFor(type);
    const std::string stem = fs::path(o.inputFile).stem().string();
    // Output_File_Name: a folder when it ends in '/', else a file name
    // whose extension is dropped only when it is the type's own (povray:
    // +Oout.tga with PNG output writes out.tga.png; the match is
    // case-sensitive).
    if (o.outputFile.empty()) {
        n.base = stem;
    } else if (o.outputFile.back() == '/') {
        n.folder = o.outputFile;
        n.base = stem;
    } else {
        const fs::path p(o.outputFile);
        n.folder = p.parent_path().string();
        n.base = p.filename().string();
        const std::string& ext = n.extension;
        if (n.base.size() > ext.size() &&
            n.base.compare(n.base.size() - ext.size(), ext.size(), ext) == 0)
            n.base.resize(n.base.size() - ext.size());
    }
    return n;
}

fs::path composeName(const NameParts& parts, bool animated, long long number, int digits) {
    std::string base = parts.base;
    if (animated) {
        const std::string n = fmt::format("{:0{}d}", number, digits);
        // The name keeps its length: a frame number longer than the padding
        // eats into the base name (povray: abcdef99 then abcde100).
        const size_t extra = n.size() > static_cast<size_t>(digits) ? n.size() - digits : 0;
        base.resize(base.size() > extra ? base.size() - extra : 0);
        base += n;
    }
    return parts.folder.empty() ? fs::path(base + parts.extension)
                                : fs::path(parts.folder) / (base + parts.extension);
}

}  // namespace

fs::path outputName(const options::RenderOptions& o, image::FileType type, bool animated,
                    int number, int digits) {
    return composeName(nameParts(o, type), animated, number, digits);
}

FrameSpec FrameList::operator[](size_t i) const {
    if (!animated_) return still_;
    FrameSpec f;
    const long long n = first_ + (offset_ + static_cast<long long>(i) * stride_) * step_;
    f.number = static_cast<int>(n);
    f.clock = static_cast<float>(clockStart_ + static_cast<double>(n - initial_) * clockStep_);
    f.clockDelta = delta_;
    f.animated = true;
    f.output = composeName({folder_.string(), base_, extension_}, true, n, digits_);
    f.log = fs::path(f.output).replace_extension(".log");
    return f;
}

bool FrameList::holdsImageNamed(const std::string& fileName) const {
    if (count_ == 0) return false;
    if (!animated_) return fileName == still_.output.filename().string();
    // Frame numbers never have more digits than the padding (it is the
    // final frame's), so a name is the base, `digits_` digits and the
    // extension.
    const size_t fixed = base_.size() + extension_.size();
    if (fileName.size() != fixed + static_cast<size_t>(digits_) ||
        fileName.compare(0, base_.size(), base_) != 0 ||
        fileName.compare(fileName.size() - extension_.size(), extension_.size(), extension_) != 0)
        return false;
    const std::string digits = fileName.substr(base_.size(), static_cast<size_t>(digits_));
    if (digits.find_first_not_of("0123456789") != std::string::npos) return false;
    const long long n = std::stoll(digits);
    const long long steps = n - first_;
    if (steps < 0 || steps % step_ != 0) return false;
    const long long position = steps / step_ - offset_;
    return position >= 0 && position % stride_ == 0 &&
           static_cast<size_t>(position / stride_) < count_;
}

namespace {

// Subset_Start_Frame / Subset_End_Frame: 0 or at least 1 is a frame
// number; between them a fraction of the frame count, counted from frame
// 0 (povray 3.7: +KFI5 +KFF15 +EF0.8 ends at frame 8).
int subsetFrame(double value, int initial, long long final) {
    const double v = std::max(value, 0.0);
    if (v == 0.0 || v >= 1.0) return static_cast<int>(std::min(v, static_cast<double>(INT_MAX)));
    return static_cast<int>(std::floor(v * static_cast<double>(final - initial + 1)));
}

// Start_Row & co: a start value below 1 is a fraction of the size, an end
// value up to 1 is; other values are 1-based pixel numbers. povray keeps
// these options in single precision, which shows: +EC0.7 at width 160
// ends at column 111, not 112 (0.7f * 160 = 111.9999981).
int windowFraction(double v, int size) {
    return static_cast<int>(std::floor(static_cast<double>(static_cast<float>(v)) * size));
}
int windowStart(double v, int size) {
    return v < 1.0 ? windowFraction(v, size) : static_cast<int>(v) - 1;
}
int windowEnd(double v, int size) {
    if (v < 0) return size;
    return v <= 1.0 ? windowFraction(v, size) : static_cast<int>(v);
}

}  // namespace

void checkOutputFolder(const options::RenderOptions& o, const Sequence& seq) {
    if (!o.writesImages() || seq.frames.empty() || o.outputFile == "-" ||
        (!o.outputFile.empty() && o.outputFile.back() == '/'))
        return;
    const fs::path folder = seq.frames.front().output.parent_path();
    std::error_code ec;
    if (folder.empty() || fs::is_directory(folder, ec)) return;
    throw options::OptionError(
        fmt::format("cannot write '{}': the folder '{}' does not exist (Output_File_Name '{}'; a "
                    "name ending in "
                    "'/' is a folder, which frameray creates)",
                    seq.frames.front().output.string(), folder.string(), o.outputFile));
}

Sequence planSequence(const options::RenderOptions& o) {
    Sequence seq;
    seq.fileType = fileTypeFor(o.outputType);
    seq.sceneName = fs::path(o.inputFile).stem().string();
    seq.runLogName = seq.sceneName + ".frameray.log";
    seq.sheetName = seq.sceneName;
    // The extra layers live in EXR files only; elsewhere they would be lost.
    if (!o.outputAovs.empty() && seq.fileType != image::FileType::EXR)
        throw options::OptionError(
            "Output_AOVs needs EXR frames: add +FE (Output_File_Type=E), or drop Output_AOVs");

    // Render window.
    seq.window.x0 = windowStart(o.startColumn, o.width);
    seq.window.y0 = windowStart(o.startRow, o.height);
    seq.window.x1 = windowEnd(o.endColumn, o.width);
    seq.window.y1 = windowEnd(o.endRow, o.height);
    if (seq.window.x0 < 0 || seq.window.x0 >= o.width || seq.window.y0 < 0 ||
        seq.window.y0 >= o.height)
        throw options::OptionError(
            fmt::format("invalid start column or row: Start_Column {} / Start_Row {} is outside "
                        "the {}x{} image",
                        o.startColumn, o.startRow, o.width, o.height));
    if (seq.window.x1 > o.width || seq.window.y1 > o.height)
        throw options::OptionError(fmt::format(
            "invalid end column or row: End_Column {} / End_Row {} is outside the {}x{} image",
            o.endColumn, o.endRow, o.width, o.height));

    // POV-Ray 3.7 animates when the frame numbers given (0 when not given)
    // differ, or are equal but neither 0 nor 1: +KFI1 +KFF1 is a still,
    // +KFF1 alone or +KFI3 +KFF3 a one-frame animation.
    const int givenInitial = o.initialFrameSet ? o.initialFrame : 0;
    const int givenFinal = o.finalFrameSet ? o.finalFrame : 0;
    seq.animated = givenInitial != givenFinal || (givenInitial != 0 && givenInitial != 1);

    FrameList& frames = seq.frames;
    if (!seq.animated) {
        FrameSpec& f = frames.still_;
        f.number = 0;
        // povray keeps the clock in single precision (+K0.4237 is
        // 0.42370000481605529785 in the scene).
        f.clock = o.clockSet ? static_cast<float>(o.clock) : 0.0;
        f.output = outputName(o, seq.fileType, false, 0, 0);
        f.log = fs::path(f.output).replace_extension(".log");
        seq.clockOn = o.clockSet;
        frames.count_ = 1;
    } else {
        const int initial = std::max(o.initialFrameSet ? o.initialFrame : 1, 0);
        const int lastFrame = std::max(o.finalFrameSet ? o.finalFrame : 1, initial);
        // The frame after the last is the first again.
        const long long final = lastFrame + (o.cyclicAnimation ? 1LL : 0LL);
        // A one-frame animation divides by zero: povray gives clock_delta
        // inf and clock nan, and so does this.
        const double delta = (o.finalClock - o.initialClock) / static_cast<double>(final - initial);
        const int first = o.subsetStartSet
                              ? std::max(subsetFrame(o.subsetStartFrame, initial, final), initial)
                              : initial;
        const int last = std::max(
            o.subsetEndSet ? subsetFrame(o.subsetEndFrame, initial, final) : lastFrame, first);
        seq.clockOn = true;
        seq.initialFrame = initial;
        seq.finalFrame = static_cast<int>(std::min<long long>(final, INT_MAX));
        seq.initialClock = o.initialClock;
        seq.finalClock = o.finalClock;
        frames.animated_ = true;
        frames.first_ = first;
        frames.step_ = std::max(o.frameStep, 1);
        frames.count_ =
            static_cast<size_t>((static_cast<long long>(last) - first) / frames.step_ + 1);
        frames.initial_ = initial;
        frames.delta_ = delta;
        const float start = static_cast<float>(o.initialClock);
        frames.clockStart_ = start;
        frames.clockStep_ = static_cast<double>(static_cast<float>(o.finalClock) - start) /
                            static_cast<double>(final - initial);
        frames.digits_ = static_cast<int>(std::to_string(final).size());
        const NameParts parts = nameParts(o, seq.fileType);
        frames.folder_ = parts.folder;
        frames.base_ = parts.base;
        frames.extension_ = parts.extension;
    }
    // The journal sits beside the images, named after the sequence.
    const fs::path firstOut = outputName(o, seq.fileType, false, 0, 0);
    seq.journal =
        firstOut.parent_path() / fmt::format(".{}.frameray-journal", firstOut.stem().string());
    seq.framesInAllShards = frames.size();
    if (o.shardCount > 1 || o.shardIndex != 0) {
        if (o.shardIndex < 0 || o.shardIndex >= o.shardCount)
            throw options::OptionError(
                fmt::format("Shard_Index {} is outside 0 to {} (Shard_Count {})", o.shardIndex,
                            o.shardCount - 1, o.shardCount));
        // Interleaved rather than in blocks: neighbouring frames cost about
        // the same, so every shard gets its share of the slow stretches.
        const auto index = static_cast<size_t>(o.shardIndex),
                   count = static_cast<size_t>(o.shardCount);
        const size_t all = frames.count_;
        frames.count_ = all > index ? (all - index + count - 1) / count : 0;
        if (!frames.animated_ && frames.count_ == 0) frames.still_ = {};
        frames.offset_ = o.shardIndex;
        frames.stride_ = o.shardCount;
        seq.shardIndex = o.shardIndex;
        seq.shardCount = o.shardCount;
        // Several processes write into one folder: each keeps its own
        // journal and statistics, named after its shard.
        const std::string tag = fmt::format("shard-{}-of-{}", o.shardIndex, o.shardCount);
        seq.journal = firstOut.parent_path() /
                      fmt::format(".{}.{}.frameray-journal", firstOut.stem().string(), tag);
        seq.statisticsName = fmt::format("sequence.{}.json", tag);
        seq.runLogName = fmt::format("{}.{}.frameray.log", seq.sceneName, tag);
        seq.sheetName = fmt::format("{}.{}", seq.sceneName, tag);
    }
    return seq;
}

}  // namespace frameray::anim
