#include "sdl/token_cache.h"

#include <fstream>

#include "sdl/lexer.h"

namespace frameray::sdl {

namespace fs = std::filesystem;

std::shared_ptr<const TokenizedFile> TokenCache::get(const fs::path& path) {
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(path, ec);
    const std::string key = (ec ? path : canonical).string();
    const auto size = fs::file_size(path, ec);
    if (ec) return nullptr;
    const auto mtime = fs::last_write_time(path, ec);
    if (ec) return nullptr;

    std::ifstream in(path, std::ios::binary);
    if (!in) return nullptr;
    // Read straight into its string: a stream buffer and a copy of it
    // would be three times a large file's size at once (issue 23).
    std::string content(static_cast<size_t>(size), '\0');
    in.read(content.data(), static_cast<std::streamsize>(size));
    content.resize(static_cast<size_t>(in.gcount()));
    // The hash guards against a rewrite within the file system's timestamp
    // granularity that kept the size (a state file rewritten every frame).
    const size_t hash = std::hash<std::string>{}(content);

    std::lock_guard lock(mutex_);
    auto it = entries_.find(key);
    if (it != entries_.end() && it->second.size == size && it->second.mtime == mtime &&
        it->second.contentHash == hash)
        return it->second.tokens;

    auto tokens = tokenize(std::make_shared<SourceFile>(path.string(), std::move(content)));
    entries_[key] = Entry{size, mtime, hash, tokens};
    return tokens;
}

std::shared_ptr<const TokenizedFile> TokenCache::fromText(const std::string& name,
                                                          const std::string& text) {
    return tokenize(std::make_shared<SourceFile>(name, text));
}

}  // namespace frameray::sdl
