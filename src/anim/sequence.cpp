#include "anim/sequence.h"

#include <fmt/format.h>

#include "options/options.h"

namespace frameray::anim {

namespace fs = std::filesystem;

image::FileType fileTypeFor(char letter) {
    switch (letter) {
        case 'P': return image::FileType::PPM;
        case 'T': case 'C': return image::FileType::TGA;
        case 'E': return image::FileType::EXR;
        case 'H': return image::FileType::HDR;
        case 'J': return image::FileType::JPEG;
        case 'B': return image::FileType::BMP;
        default: return image::FileType::PNG;
    }
}

namespace {

// POV-Ray's output naming: Output_File_Name may be a file name (its
// extension replaced by the type's) or a folder; by default the scene's
// name in the working folder. Animations append the frame number padded to
// the digit count of the final frame.
fs::path outputPath(const options::RenderOptions& o, image::FileType type, int frame, bool animated,
                    int finalFrame) {
    const fs::path scene(o.inputFile);
    fs::path base;
    if (o.outputFile.empty()) {
        base = scene.stem();
    } else {
        const bool folder = o.outputFile.back() == '/' || fs::is_directory(o.outputFile);
        base = folder ? fs::path(o.outputFile) / scene.stem() : fs::path(o.outputFile).replace_extension();
    }
    std::string name = base.filename().string();
    if (animated) {
        const int digits = static_cast<int>(std::to_string(finalFrame).size());
        name += fmt::format("{:0{}d}", frame, digits);
    }
    return base.parent_path() / (name + image::extensionFor(type));
}

}  // namespace

Sequence planSequence(const options::RenderOptions& o) {
    Sequence seq;
    seq.fileType = fileTypeFor(o.outputType);
    seq.initialFrame = o.initialFrame;
    seq.finalFrame = o.finalFrame;
    seq.initialClock = o.initialClock;
    seq.finalClock = o.finalClock;
    if (o.finalFrame < o.initialFrame)
        throw options::OptionError(fmt::format("Final_Frame {} is before Initial_Frame {}", o.finalFrame, o.initialFrame));

    const bool animated = o.finalFrame != o.initialFrame;
    if (!animated) {
        FrameSpec f;
        f.number = o.initialFrame;
        f.clock = o.clockSet ? o.clock : o.initialClock;
        f.output = outputPath(o, seq.fileType, f.number, false, o.finalFrame);
        f.log = fs::path(f.output).replace_extension(".log");
        seq.frames.push_back(f);
        return seq;
    }
    const int span = o.finalFrame - o.initialFrame + (o.cyclicAnimation ? 1 : 0);
    const double delta = (o.finalClock - o.initialClock) / span;
    const int first = o.subsetStartFrame > 0 ? std::max(o.subsetStartFrame, o.initialFrame) : o.initialFrame;
    const int last = o.subsetEndFrame > 0 ? std::min(o.subsetEndFrame, o.finalFrame) : o.finalFrame;
    for (int n = first; n <= last; ++n) {
        FrameSpec f;
        f.number = n;
        f.clock = o.initialClock + delta * (n - o.initialFrame);
        f.clockDelta = delta;
        f.animated = true;
        f.output = outputPath(o, seq.fileType, n, true, o.finalFrame);
        f.log = fs::path(f.output).replace_extension(".log");
        seq.frames.push_back(f);
    }
    return seq;
}

}  // namespace frameray::anim
