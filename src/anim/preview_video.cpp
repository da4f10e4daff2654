#include "anim/preview_video.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "anim/frame_pixels.h"
#include "image/image_io.h"
#include "util/durable_file.h"

extern char** environ;

namespace frameray::anim {

namespace fs = std::filesystem;

namespace {

struct Codec {
    std::string_view format, encoder, muxer;
    std::vector<std::string> options;  // after -c:v ENCODER
};

const Codec& codecFor(const std::string& format) {
    // yuv420p: what every player decodes; -crf: constant quality.
    static const Codec kCodecs[] = {
        {"mp4", "libx264", "mp4", {"-preset", "medium", "-crf", "18", "-movflags", "+faststart"}},
        {"webm", "libvpx-vp9", "webm", {"-crf", "32", "-b:v", "0", "-row-mt", "1"}},
    };
    for (const Codec& c : kCodecs)
        if (c.format == format) return c;
    throw std::runtime_error(fmt::format("unknown preview video format '{}'", format));
}

fs::path findProgram(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        fs::path candidate = fs::path(dir.empty() ? "." : dir) / name;
        if (access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    return {};
}

// Runs `argv` with stdin from `in` (-1: /dev/null), stdout to `out` and
// stderr to `err` (-1: /dev/null); returns its pid. Throws on failure.
pid_t spawn(const std::vector<std::string>& argv, int in, int out, int err) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    const auto route = [&](int fd, int target, int flags) {
        if (fd >= 0)
            posix_spawn_file_actions_adddup2(&actions, fd, target);
        else
            posix_spawn_file_actions_addopen(&actions, target, "/dev/null", flags, 0);
    };
    route(in, STDIN_FILENO, O_RDONLY);
    route(out, STDOUT_FILENO, O_WRONLY);
    route(err, STDERR_FILENO, O_WRONLY);
    std::vector<char*> args;
    args.reserve(argv.size() + 1);
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    pid_t pid = 0;
    const int rc = posix_spawn(&pid, argv[0].c_str(), &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0)
        throw std::runtime_error(fmt::format("cannot run {}: {}", argv[0], std::strerror(rc)));
    return pid;
}

int waitFor(pid_t pid) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// Everything a file descriptor gives until its end.
std::string drain(int fd) {
    std::string text;
    char buffer[4096];
    for (;;) {
        const ssize_t n = read(fd, buffer, sizeof buffer);
        if (n > 0)
            text.append(buffer, static_cast<size_t>(n));
        else if (n == 0 || errno != EINTR)
            break;
    }
    return text;
}

fs::path ffmpegProgram() {
    fs::path ffmpeg = findProgram("ffmpeg");
    if (ffmpeg.empty())
        throw std::runtime_error(
            "Preview_Video needs the ffmpeg program, which is not on PATH (Debian package "
            "ffmpeg; scripts/setup.sh installs it)");
    return ffmpeg;
}

// Writes all of `bytes` to a socket; false when the reader went away (no
// SIGPIPE: the socket is written with MSG_NOSIGNAL).
bool sendAll(int fd, const std::uint8_t* bytes, size_t size) {
    while (size > 0) {
        const ssize_t n = send(fd, bytes, size, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        bytes += n;
        size -= static_cast<size_t>(n);
    }
    return true;
}

std::vector<std::string> encodeArguments(const fs::path& ffmpeg, const Codec& codec, int width,
                                         int height, double fps, const fs::path& output) {
    std::vector<std::string> argv = {
        ffmpeg.string(), "-hide_banner", "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt",
        "rgb24", "-s", fmt::format("{}x{}", width, height), "-framerate", fmt::format("{}", fps),
        "-i", "pipe:0",
        // 4:2:0 needs even sizes: an odd row or column is repeated.
        "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", std::string(codec.encoder)};
    argv.insert(argv.end(), codec.options.begin(), codec.options.end());
    // No encoder version or time in the file: the same frames give the same video.
    argv.insert(argv.end(),
                {"-pix_fmt", "yuv420p", "-fflags", "+bitexact", "-flags:v", "+bitexact",
                 "-map_metadata", "-1", "-f", std::string(codec.muxer), output.string()});
    return argv;
}

}  // namespace

void checkVideoEncoder(const std::string& format) {
    const Codec& codec = codecFor(format);
    const fs::path ffmpeg = ffmpegProgram();
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0)
        throw std::runtime_error(fmt::format("cannot run ffmpeg: {}", std::strerror(errno)));
    pid_t pid = 0;
    try {
        pid = spawn({ffmpeg.string(), "-hide_banner", "-encoders"}, -1, fds[1], -1);
    } catch (...) {
        close(fds[0]);
        close(fds[1]);
        throw;
    }
    close(fds[1]);
    const std::string list = drain(fds[0]);
    close(fds[0]);
    waitFor(pid);
    if (list.find(fmt::format(" {} ", codec.encoder)) == std::string::npos)
        throw std::runtime_error(fmt::format(
            "Preview_Video={} needs ffmpeg's {} encoder, which {} does not have (Debian's ffmpeg "
            "has it)",
            format, codec.encoder, ffmpeg.string()));
}

void makePreviewVideo(const std::vector<fs::path>& frames, const fs::path& output,
                      const std::string& format, double fps) {
    if (frames.empty()) throw std::runtime_error("no frames for the preview video");
    const Codec& codec = codecFor(format);
    const fs::path ffmpeg = ffmpegProgram();
    const Rgb8Image first = readRgb8(frames.front());
    const fs::path temporary = image::temporaryPathFor(output);
    const fs::path messages = fs::path(temporary).concat(".log");
    int sockets[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sockets) != 0)
        throw std::runtime_error(fmt::format("cannot run ffmpeg: {}", std::strerror(errno)));
    const int err = util::createNoFollow(messages);
    pid_t pid = 0;
    try {
        pid = spawn(encodeArguments(ffmpeg, codec, first.width, first.height, fps, temporary),
                    sockets[1], -1, err);
    } catch (...) {
        close(sockets[0]);
        close(sockets[1]);
        close(err);
        throw;
    }
    close(sockets[1]);
    close(err);
    std::string problem;
    bool open = sendAll(sockets[0], first.rgb.data(), first.rgb.size());
    for (size_t i = 1; open && i < frames.size() && problem.empty(); ++i) {
        try {
            const Rgb8Image frame = readRgb8(frames[i]);
            if (frame.width != first.width || frame.height != first.height)
                problem = fmt::format("'{}' is {}x{}, the first frame {}x{}", frames[i].string(),
                                      frame.width, frame.height, first.width, first.height);
            else
                open = sendAll(sockets[0], frame.rgb.data(), frame.rgb.size());
        } catch (const std::exception& e) {
            problem = e.what();
        }
    }
    close(sockets[0]);
    const int code = waitFor(pid);
    std::ifstream log(messages);
    const std::string said((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
    std::error_code ec;
    fs::remove(messages, ec);
    if (problem.empty() && (code != 0 || !open))
        problem = fmt::format("ffmpeg ({} encoder) failed with exit code {}: {}", codec.encoder,
                              code, said.empty() ? std::string("no message") : said);
    if (!problem.empty()) {
        fs::remove(temporary, ec);
        throw std::runtime_error(fmt::format("cannot make '{}': {}", output.string(), problem));
    }
    util::renameDurably(temporary, output);
}

}  // namespace frameray::anim
