#include "image/codecs.h"

#include <dlfcn.h>
#include <fmt/format.h>
#include <unistd.h>

#include <filesystem>
#include <future>
#include <mutex>
#include <stdexcept>

namespace frameray::image {

namespace fs = std::filesystem;

namespace {

constexpr const char* kModuleName = "libframeray_oiio.so";

// Beside the executable (the build tree's bin/), then ../lib/frameray/ (an
// installed layout), then the dynamic loader's own search path.
const CodecTable* loadModule() {
    std::vector<std::string> candidates;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        candidates.push_back((exe.parent_path() / kModuleName).string());
        candidates.push_back(
            (exe.parent_path().parent_path() / "lib" / "frameray" / kModuleName).string());
    }
    candidates.emplace_back(kModuleName);
    std::string reasons;
    for (const std::string& candidate : candidates) {
        if (candidate.find('/') != std::string::npos && !fs::exists(candidate, ec)) continue;
        void* handle = ::dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            reasons += fmt::format("\n  {}: {}", candidate, ::dlerror());
            continue;
        }
        // Never closed: the module lives as long as the process.
        using Entry = const CodecTable* (*)();
        const auto entry = reinterpret_cast<Entry>(::dlsym(handle, "frameray_oiio_codecs"));
        if (!entry)
            throw std::runtime_error(
                fmt::format("{} has no entry point frameray_oiio_codecs", candidate));
        return entry();
    }
    throw std::runtime_error(
        fmt::format("cannot load the image module {} (OpenImageIO) beside {}{}", kModuleName,
                    exe.string(), reasons));
}

// The process's one module load: immutable once loaded, shared by every
// frame (this is a cache of a shared library, not parse or render state).
class ModuleLoader {
  public:
    void start() {
        std::call_once(started_,
                       [this] { table_ = std::async(std::launch::async, loadModule).share(); });
    }
    const CodecTable& get() {
        start();
        return *table_.get();
    }

  private:
    std::once_flag started_;
    std::shared_future<const CodecTable*> table_;
};

ModuleLoader& loader() {
    static ModuleLoader instance;
    return instance;
}

}  // namespace

void preloadCodecs() {
    loader().start();
}

const CodecTable& codecs() {
    return loader().get();
}

}  // namespace frameray::image
