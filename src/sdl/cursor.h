// Where the reader stands: one cursor per open token stream (the scene
// file, the include files open, the macro calls in progress) and the
// directive blocks (#if, loops, #switch, macro bodies) open in them.
#pragma once

#include <memory>
#include <string>

#include "sdl/token.h"
#include "sdl/value.h"

namespace frameray::sdl {

enum class CursorKind { File, Macro };

struct Cursor {
    std::shared_ptr<const TokenizedFile> file;
    size_t pos = 0;
    CursorKind kind = CursorKind::File;
    size_t scopeCount = 0;  // scopes to restore when it ends
    size_t blockCount = 0;  // blocks to restore when it ends
    // True while a directive's own arguments are read from this cursor:
    // a '#' met then ends the argument instead of starting a directive
    // (the expression parser's one-token lookahead must not run the
    // next line's directive before this one is done).
    bool inDirective = false;
    // Where the #include or the macro call that opened this cursor
    // stands, and the macro's name, for the chain in diagnostics.
    SourceLoc callSite{};
    std::string macroName{};
};

enum class BlockKind { If, While, For, Switch, Macro };

struct Block {
    Block() = default;
    Block(BlockKind k, const SourceLoc& l) : kind(k), loc(l) {}
    BlockKind kind = BlockKind::If;
    SourceLoc loc;
    size_t restartPos = 0;  // While: the '#' of the directive; For: after the header
    std::string loopVar;    // For
    double loopEnd = 0, loopStep = 1;
    double switchValue = 0;  // Switch
    bool elseTaken = false;  // If: running its #else branch (a second #else is an error)
};

// Where peek() last resolved the stream to a plain token, so repeated
// peeks at the same place (every precedence level looks) skip the
// directive and macro checks.
struct PeekCache {
    const TokenizedFile* file = nullptr;
    size_t pos = 0;
    size_t depth = 0;
    // For an identifier: what it names (nullptr if undeclared), so the
    // caller that consumes it need not look it up again.
    const Value* identifier = nullptr;
};

// Where a #declare's value is being read (cursor depth, -1: none) and how
// many parentheses, vector brackets or argument lists are open in it (see
// Reader::peekAfterOperand).
struct DeclareValueState {
    int cursorDepth = -1;
    int grouping = 0;
};

// Counts one more open grouping while it lives.
class GroupingGuard {
  public:
    explicit GroupingGuard(DeclareValueState& s) : s_(s) { ++s_.grouping; }
    ~GroupingGuard() { --s_.grouping; }
    GroupingGuard(const GroupingGuard&) = delete;
    GroupingGuard& operator=(const GroupingGuard&) = delete;

  private:
    DeclareValueState& s_;
};

}  // namespace frameray::sdl
