// The contact sheet (Contact_Sheet=on, issue 29): beside an animation's
// frames, NAME.html — every frame as a thumbnail with its number, clock,
// render time and rays (the figures sequence.json holds), failed frames
// marked, frames still to come as empty cells, and a player (play/pause,
// step, a slider, the arrow keys; `?frame=N` opens frame N, `?step=K`
// steps K frames from the first, for scripted checks) — and NAME-sheet.png,
// the thumbnails in a grid (a failed frame red, a missing one grey).
//
// The page is self-contained: the thumbnails are PNG data: URIs in it, so
// it can be mailed or copied alone and is never out of step with a folder
// of thumbnail files; the player's large view shows the frame file itself
// when the browser can (PNG, JPEG, BMP beside the page), else the
// thumbnail. Thumbnails are at most 160 x 120 (a few kB each).
//
// Both files are rewritten through util/durable_file (temporary + rename)
// as frames finish, at most once every two seconds, and once at the end:
// a reader never sees half a page. Frames kept by +C appear with their
// thumbnail read from the file. A shard writes its own page
// (NAME.shard-I-of-N.html) with its frames.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "anim/frame_pixels.h"
#include "anim/sequence.h"

namespace frameray::anim {

inline constexpr int kThumbnailWidth = 160, kThumbnailHeight = 120;

struct SheetFrame {
    enum class State { Pending, Rendered, Kept, Failed };
    int number = 0;
    double clock = 0;
    std::string file;  // the image's name, beside the page
    State state = State::Pending;
    double seconds = 0;        // parse + prepare + render + write (Rendered)
    std::uint64_t rays = 0;    // every ray the frame traced (Rendered)
    std::string failure;       // Failed: the message
    Rgb8Image thumbnail;       // empty: none
    std::string thumbnailPng;  // its PNG file's bytes
};

// The page's text for these frames (pure: the unit tests call it).
std::string contactSheetHtml(const std::string& title, const std::vector<SheetFrame>& frames,
                             double fps);
// The grid image of the thumbnails, `columns` wide.
Rgb8Image contactSheetGrid(const std::vector<SheetFrame>& frames, int columns);

class ContactSheet {
  public:
    // Every frame of `seq` starts pending (past kMaxListed frames only the
    // frames seen are listed).
    ContactSheet(const Sequence& seq, double fps);

    void rendered(const FrameSpec& frame, double seconds, std::uint64_t rays,
                  const Rgb8Image& thumbnail);
    // A frame finished by an earlier run: its thumbnail from the file.
    void kept(const FrameSpec& frame);
    void failed(const FrameSpec& frame, const std::string& why);

    // Rewrites the page and the grid when `final` or two seconds have
    // passed since the last time; throws std::runtime_error naming the
    // file that could not be written.
    void save(bool final);

    std::filesystem::path pagePath() const { return folder_ / (name_ + ".html"); }
    std::filesystem::path gridPath() const { return folder_ / (name_ + "-sheet.png"); }

    static constexpr size_t kMaxListed = 10000;

  private:
    SheetFrame& slot(const FrameSpec& frame);

    std::filesystem::path folder_;
    std::string name_;
    double fps_;
    std::map<int, SheetFrame> frames_;  // by frame number
    std::optional<std::chrono::steady_clock::time_point> lastSave_;
};

}  // namespace frameray::anim
