// The frames of a run: frame numbers, clock values, output names and the
// render window, computed from the options exactly as POV-Ray 3.7 does.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "image/frame_encoding.h"
#include "image/image_io.h"
#include "options/render_options.h"

namespace frameray::anim {

struct Sequence;
Sequence planSequence(const options::RenderOptions& options);

struct FrameSpec {
    int number = 0;  // frame_number
    double clock = 0;
    double clockDelta = 0;
    bool animated = false;
    std::filesystem::path output;  // final image path
    std::filesystem::path log;     // the frame's message log, beside the image
};

// The render window in 0-based pixel coordinates, end exclusive.
using RenderWindow = image::RenderWindow;

// The frames of a run (one shard's), each computed when asked for: a
// sequence of 2 000 000 000 frames is planned in constant time and memory,
// and a subset or shard of it is exact.
class FrameList {
  public:
    size_t size() const { return count_; }
    bool empty() const { return count_ == 0; }
    FrameSpec operator[](size_t i) const;
    FrameSpec front() const { return (*this)[0]; }
    FrameSpec back() const { return (*this)[count_ - 1]; }
    // Whether `fileName` (no folder) is the image of one of these frames.
    bool holdsImageNamed(const std::string& fileName) const;

    class iterator {
      public:
        using value_type = FrameSpec;
        using difference_type = std::ptrdiff_t;
        iterator(const FrameList* list, size_t i) : list_(list), i_(i) {}
        FrameSpec operator*() const { return (*list_)[i_]; }
        iterator& operator++() {
            ++i_;
            return *this;
        }
        bool operator==(const iterator& o) const { return i_ == o.i_; }

      private:
        const FrameList* list_;
        size_t i_;
    };
    iterator begin() const { return {this, 0}; }
    iterator end() const { return {this, count_}; }

  private:
    friend Sequence planSequence(const options::RenderOptions& options);
    bool animated_ = false;
    FrameSpec still_;  // the frame of a still image
    // Animation: the frame at position i is number first_ + (offset_ + i *
    // stride_) * step_ (offset_ and stride_ pick a shard's frames).
    long long first_ = 0, step_ = 1, offset_ = 0, stride_ = 1;
    size_t count_ = 0;
    int initial_ = 0, digits_ = 1;
    double delta_ = 0;
    // povray 3.7 keeps the clock in single precision: its start, and its
    // step (the difference of the single-precision end points, divided in
    // double precision) from which each frame's clock is summed in double
    // and then rounded to single precision (measured against povray's
    // clock for several ranges, cyclic or not, to the last bit).
    double clockStart_ = 0, clockStep_ = 0;
    std::filesystem::path folder_;
    std::string base_, extension_;
};

struct Sequence {
    FrameList frames;
    image::FileType fileType = image::FileType::PNG;
    bool animated = false;
    bool clockOn = false;  // clock_on: an animation, or Clock given
    // The built-in identifiers initial_frame, final_frame (one more than
    // Final_Frame in a cyclic animation), initial_clock, final_clock: all 0
    // when not animated, as in POV-Ray.
    int initialFrame = 0, finalFrame = 0;
    double initialClock = 0, finalClock = 0;
    RenderWindow window;
    // The journal of finished frames, beside the images (Continue_Trace).
    std::filesystem::path journal;
    std::string sceneName;  // the scene file's name without folder and extension (%s)
    // Shard_Index / Shard_Count: `frames` holds this shard's frames only;
    // the journal and the statistics file are the shard's own.
    int shardIndex = 0, shardCount = 1;
    size_t framesInAllShards = 0;
    std::string statisticsName = "sequence.json";
    // frameray's run log beside the frames (anim/run_log.h): NAME.frameray.log,
    // a shard's NAME.shard-I-of-N.frameray.log.
    std::string runLogName;
    // The contact sheet's base name (NAME.html, NAME-sheet.png): the scene's
    // name, a shard's NAME.shard-I-of-N.
    std::string sheetName;
};

// Throws options::OptionError when the options make no sense (a render
// window outside the image).
Sequence planSequence(const options::RenderOptions& options);

// Throws options::OptionError when the images' folder does not exist and
// Output_File_Name does not name it as a folder (ending in '/'): povray
// refuses such a name, and creating a mistyped path would be worse.
void checkOutputFolder(const options::RenderOptions& options, const Sequence& sequence);

// POV-Ray's output name of frame `number`: the name without its extension
// when that is the type's, the frame number padded to `digits` (the base
// name is shortened when the number has more digits), the extension.
std::filesystem::path outputName(const options::RenderOptions& options, image::FileType type,
                                 bool animated, int number, int digits);

image::FileType fileTypeFor(char letter);

}  // namespace frameray::anim
