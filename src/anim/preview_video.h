// The preview video (Preview_Video=mp4|webm, issue 29): once every frame
// of a sequence exists, NAME.mp4 (H.264) or NAME.webm (VP9) beside the
// frames, one video frame per image at Preview_Fps.
//
// Made by the `ffmpeg` program (Debian's ffmpeg, built with libx264 and
// libvpx) rather than by linking libavcodec/libavformat: the libraries'
// API changes between FFmpeg versions (Debian 12 has 5.1; encoders and
// muxers are set up through many deprecated-then-removed calls), linking
// them would load ~40 more shared libraries into every frameray process,
// most of which never makes a video, and libx264 is GPL. The program's
// options are stable across versions, and a missing program or encoder is
// found and named before any frame is rendered. frameray decodes the
// frames itself (anim/frame_pixels.h) and pipes them as raw RGB, so the
// video holds exactly the sequence's frames in order, whatever their
// names, steps or gaps.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace frameray::anim {

// Throws std::runtime_error naming what is missing: the ffmpeg program on
// PATH, or its encoder for `format` ("mp4": libx264, "webm": libvpx-vp9).
void checkVideoEncoder(const std::string& format);

// Encodes `frames` (image files of one size, in order) into `output`
// through a temporary beside it, renamed into place when ffmpeg succeeds;
// the frames are only read. Throws std::runtime_error with ffmpeg's own
// message on failure (no partial file is left under `output`).
void makePreviewVideo(const std::vector<std::filesystem::path>& frames,
                      const std::filesystem::path& output, const std::string& format, double fps);

}  // namespace frameray::anim
