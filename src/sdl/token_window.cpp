#include "sdl/token_window.h"

namespace frameray::sdl {

const Token& TokenWindow::inChunk(const std::shared_ptr<const TokenizedFile>& file, size_t pos) {
    const size_t chunk = pos / TokenizedFile::kChunkTokens;
    const size_t offset = pos % TokenizedFile::kChunkTokens;
    const TokenizedFile::Chunk& where = file->chunks[chunk];
    if (where.kept != TokenizedFile::kNotKept) return file->tokens[where.kept + offset];

    Slot* slot = &slots_[recent_];
    if (slot->file != file || slot->chunk != chunk) {
        // Another slot holding it, else the one least recently used.
        size_t found = kSlots, oldest = 0;
        for (size_t i = 0; i < kSlots; ++i) {
            if (slots_[i].file == file && slots_[i].chunk == chunk) {
                found = i;
                break;
            }
            if (slots_[i].lastUse < slots_[oldest].lastUse) oldest = i;
        }
        if (found == kSlots) {
            found = oldest;
            Slot& s = slots_[found];
            s.file = file;
            s.chunk = chunk;
            file->relex(chunk, s.tokens.data());
        }
        recent_ = found;
        slot = &slots_[found];
    }
    slot->lastUse = ++uses_;
    return slot->tokens[offset];
}

}  // namespace frameray::sdl
