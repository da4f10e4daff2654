// The tokens of large files that are not kept (TokenizedFile: chunks lexed
// again when read), as the Reader reads them. Each Reader has its own
// window, so files shared between frames stay immutable.
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "sdl/token.h"

namespace frameray::sdl {

class TokenWindow {
  public:
    // Token `pos` of `file`. The reference stays valid while the window
    // serves fewer than kSlots other chunks (the Reader holds a token's
    // reference only across a look at the next one or two); tokens of kept
    // chunks and of small files are the file's own.
    const Token& at(const std::shared_ptr<const TokenizedFile>& file, size_t pos) {
        if (file->chunks.empty()) [[likely]]
            return file->tokens[pos];
        return inChunk(file, pos);
    }

    static constexpr size_t kSlots = 16;

  private:
    const Token& inChunk(const std::shared_ptr<const TokenizedFile>& file, size_t pos);

    struct Slot {
        // Held so that a file freed and another made at its address is
        // never taken for it.
        std::shared_ptr<const TokenizedFile> file;
        size_t chunk = 0;
        uint64_t lastUse = 0;
        std::array<Token, TokenizedFile::kChunkTokens> tokens;
    };
    std::array<Slot, kSlots> slots_;
    size_t recent_ = 0;  // the slot served last
    uint64_t uses_ = 0;
};

}  // namespace frameray::sdl
