// Tokenized files shared across the frames of a sequence: an include or
// macro file is read and lexed once, not once per frame. An entry is
// re-validated against the file's size and modification time (and content
// when those match but the file was written during the run), so a file a
// frame wrote with #write is seen afresh by the next frame.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "sdl/token.h"

namespace frameray::sdl {

class TokenCache {
public:
    // Returns the tokens of `path`, lexing it if it is new or changed.
    // Throws SdlError on a lexical error; returns nullptr when the file
    // cannot be read.
    std::shared_ptr<const TokenizedFile> get(const std::filesystem::path& path);

    // Tokens of text that is not a file (command-line declarations, tests).
    static std::shared_ptr<const TokenizedFile> fromText(const std::string& name,
                                                         const std::string& text);

private:
    struct Entry {
        std::uintmax_t size = 0;
        std::filesystem::file_time_type mtime;
        size_t contentHash = 0;
        std::shared_ptr<const TokenizedFile> tokens;
    };
    std::mutex mutex_;
    std::map<std::string, Entry> entries_;
};

}  // namespace frameray::sdl
