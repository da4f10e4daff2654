// The directives of the scene language (#declare, #include, #if, #while,
// #for, #switch, #macro, #undef, #version, messages; #fopen and friends
// are in file_io.cpp) and the macro calls they set up.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "sdl/reader.h"
#include "sdl/value_builders.h"

namespace frameray::sdl {

namespace fs = std::filesystem;

namespace {
constexpr double kEpsilon = 1e-10;  // the language's equality/truth epsilon
}  // namespace

// --- directives ----------------------------------------------------------------

void Reader::runDirective() {
    const size_t hashPos = cursors_.back().pos;
    const Token hash = rawPeek();
    const NestingGuard nesting(*this, hash);
    ++cursors_.back().pos;
    const Token word = rawPeek();
    // povray drops a '#' that a symbol follows, silently (the example
    // language/image_size.pov has `look_at <0,2,0>#` before the camera's '}').
    if (word.kind == TokenKind::Symbol) return;
    if (word.kind != TokenKind::Word || word.kw == Keyword::None)
        fail(word, fmt::format("expected a directive after '#', found {}", describeToken(word)));
    ++cursors_.back().pos;
    // Marks this cursor as reading directive arguments until we return.
    struct ArgumentMode {
        Reader& self;
        size_t index;
        ArgumentMode(Reader& s, size_t i) : self(s), index(i) {
            self.cursors_[index].inDirective = true;
        }
        ~ArgumentMode() {
            if (index < self.cursors_.size()) self.cursors_[index].inDirective = false;
        }
    } argumentMode(*this, cursors_.size() - 1);
    switch (word.kw) {
        case Keyword::kw_declare:
            directiveDeclare(false);
            break;
        case Keyword::kw_local:
            directiveDeclare(true);
            break;
        case Keyword::kw_include:
            directiveInclude(word);
            break;
        case Keyword::kw_if:
            directiveIf(word, &Reader::conditionExpression);
            break;
        case Keyword::kw_ifdef:
            directiveIf(word, &Reader::conditionIfdef);
            break;
        case Keyword::kw_ifndef:
            directiveIf(word, &Reader::conditionIfndef);
            break;
        case Keyword::kw_else:
        case Keyword::kw_elseif:
            directiveElse(word);
            break;
        case Keyword::kw_end:
            directiveEnd(word);
            break;
        case Keyword::kw_while:
            directiveWhile(word, hashPos);
            break;
        case Keyword::kw_for:
            directiveFor(word);
            break;
        case Keyword::kw_switch:
            directiveSwitch(word);
            break;
        case Keyword::kw_case:
        case Keyword::kw_range:
            // Reached while executing a case above: fall through, ignoring
            // this label's values.
            if (blocks_.empty() || blocks_.back().kind != BlockKind::Switch)
                fail(word, fmt::format("#{} outside #switch", word.text));
            if (word.kw == Keyword::kw_range) {
                expect(Sym::LParen, "'('");
                parseFloat();
                expect(Sym::Comma, "','");
                parseFloat();
                expect(Sym::RParen, "')'");
            } else {
                parseParenthesizedFloat();
            }
            break;
        case Keyword::kw_break:
            directiveBreak(word);
            break;
        case Keyword::kw_macro:
            directiveMacro(word);
            break;
        case Keyword::kw_version: {
            if (!versionSeen_ && builders_->sceneHasObjects()) declarationBeforeVersion_ = true;
            version_ = parseFloat();
            versionSeen_ = true;
            accept(Sym::Semicolon);
            break;
        }
        case Keyword::kw_undef: {
            symbols_.undefine(expectIdentifier());
            break;
        }
        case Keyword::kw_default:
            builders_->defaultDirective();
            break;
        case Keyword::kw_fopen:
            directiveFopen(word);
            break;
        case Keyword::kw_fclose:
            directiveFclose(word);
            break;
        case Keyword::kw_read:
            directiveRead(word);
            break;
        case Keyword::kw_write:
            directiveWrite(word);
            break;
        case Keyword::kw_debug:
            directiveMessage(Stream::Debug);
            break;
        case Keyword::kw_warning:
            directiveMessage(Stream::Warning);
            break;
        case Keyword::kw_render:
            directiveMessage(Stream::Render);
            break;
        case Keyword::kw_statistics:
            directiveMessage(Stream::Statistics);
            break;
        case Keyword::kw_error: {
            const std::string text = parseString();
            fail(word, fmt::format("#error: {}", text));
        }
        default:
            (void)hash;
            unsupported(word, fmt::format("#{}", word.text));
    }
}

void Reader::directiveDeclare(bool local) {
    if (!versionSeen_) declarationBeforeVersion_ = true;
    bool deprecated = false, deprecatedOnce = false;
    std::string deprecatedMessage;
    if (rawPeek().is(Keyword::kw_deprecated)) {
        ++cursors_.back().pos;
        deprecated = true;
        if (rawPeek().is(Keyword::kw_once)) {
            ++cursors_.back().pos;
            deprecatedOnce = true;
        }
        if (rawPeek().kind == TokenKind::String) {
            deprecatedMessage = std::string(rawPeek().text);
            ++cursors_.back().pos;
        }
    }
    const Token nameToken = rawPeek();
    const std::string name = expectIdentifier();
    // `#declare A[i][j] = value` assigns one array element.
    if (rawPeek().is(Sym::LBracket)) {
        Value* arr = symbols_.find(name);
        if (!arr || !std::holds_alternative<ArrayPtr>(*arr))
            fail(nameToken, fmt::format("'{}' is not an array", name));
        const ArrayPtr array = std::get<ArrayPtr>(*arr);
        const size_t index = parseArrayIndex(*array, nameToken);
        expect(Sym::Equal, "'='");
        cursors_.back().inDirective = false;
        const Token valueStart = peek();
        Value value = parseRValue();
        setArrayElement(*array, index, std::move(value), valueStart);
        acceptSemicolonBeforeDirective();
        return;
    }
    expect(Sym::Equal, "'='");
    // povray 3.7 keeps functions apart: a visible function identifier is
    // never redeclared (not even by a #local in a macro) until #undef'd.
    const Value* existing = lookup(nameToken);
    if (existing && std::holds_alternative<FunctionPtr>(*existing))
        fail(nameToken,
             fmt::format("redeclaring the function '{}' is not allowed; #undef it first", name));
    const char* existingKind = existing ? valueKindName(*existing) : nullptr;
    const size_t scopeCount = symbols_.size();
    // The value is ordinary scene text again: objects hold directives, and
    // so may expressions (`(1 + #if (A) 2 #else 3 #end)`).
    cursors_.back().inDirective = false;
    const DeclareValueState outer = declareValue_;
    declareValue_ = {static_cast<int>(cursors_.size()), 0};
    Value value;
    try {
        value = parseRValue();
    } catch (...) {
        declareValue_ = outer;
        throw;
    }
    declareValue_ = outer;
    if (existingKind && std::holds_alternative<FunctionPtr>(value))
        fail(nameToken,
             fmt::format("cannot redefine the {} identifier '{}' as a function; #undef it first",
                         existingKind, name));
    const bool needsSemicolon =
        std::holds_alternative<double>(value) || std::holds_alternative<VectorValue>(value);
    if (deprecated)
        symbols_.deprecate(name,
                           deprecatedMessage.empty()
                               ? fmt::format("Identifier '{}' was declared deprecated.", name)
                               : deprecatedMessage,
                           deprecatedOnce);
    // Bind before looking for the optional ';': that look-ahead may run the
    // next line's directive, which may use this identifier.
    symbols_.declare(name, std::move(value), local, scopeCount, nameToken.nameHash);
    // povray 3.7: an error from language version 3.5 on, a warning before.
    // rawPeek: a directive after the value must not run inside this one.
    if (needsSemicolon && !rawPeek().is(Sym::Semicolon)) {
        const std::string message = fmt::format(
            "missing ';' after the declaration of '{}': float, vector and color declarations need "
            "one",
            name);
        if (version_ >= 3.5 - 1e-9) fail(nameToken, message + " (since #version 3.5)");
        warn(nameToken, message);
    }
    acceptSemicolonBeforeDirective();
}

void Reader::acceptSemicolonBeforeDirective() {
    // A directive right after the value is left for the statement loop
    // instead of running inside this one: a list of declarations must not
    // nest as deep as it is long.
    const size_t index = cursors_.size() - 1;
    const bool was = cursors_[index].inDirective;
    cursors_[index].inDirective = true;
    const bool semicolon = peek().is(Sym::Semicolon);
    if (index < cursors_.size()) cursors_[index].inDirective = was;
    if (semicolon) next();
}

Value Reader::parseRValue() {
    const Token start = peek();
    const NestingGuard nesting(*this, start);
    switch (start.kw) {
        case Keyword::kw_transform:
            return std::make_shared<const Transform>(parseTransformBlock());
        case Keyword::kw_array:
            return parseArrayDeclaration();
        case Keyword::kw_spline:
            return parseSpline();
        case Keyword::kw_function:
            return parseFunctionDeclaration();
        default:
            break;
    }
    // Objects, textures, cameras...: what the statement builders make.
    if (start.kind == TokenKind::Word && start.kw != Keyword::None)
        if (std::optional<Value> built = builders_->buildValue(start)) return std::move(*built);
    // A string value is complete without looking further (see parseString).
    if (startsStringExpression(start)) return parseString();
    Value v = parseExpression();
    // Arrays are values: a declaration from another array copies it.
    if (auto* arr = std::get_if<ArrayPtr>(&v)) {
        chargeArrayElements((*arr)->size(), start);
        return std::make_shared<ArrayValue>(**arr);
    }
    return v;
}

fs::path Reader::findIncludeFile(const std::string& name) const {
    std::error_code ec;
    const fs::path p(name);
    if (p.is_absolute()) return fs::exists(p, ec) ? p : fs::path();
    std::vector<fs::path> dirs;
    // povray 3.7's order: the working folder, then the library path. The
    // including file's own folder comes last, where povray would fail.
    dirs.push_back(fs::current_path(ec));
    for (const auto& lib : frame_.libraryPaths) dirs.push_back(lib);
    dirs.push_back(fs::path(cursors_.back().file->source->path()).parent_path());
    for (const auto& dir : dirs) {
        fs::path candidate = dir / p;
        if (fs::is_regular_file(candidate, ec)) return candidate;
    }
    return {};
}

void Reader::directiveInclude(const Token& at) {
    const std::string name = parsePathname();
    if (includeDepth_ >= frame_.limits.includeFiles)
        fail(at,
             fmt::format("#include nested more than {} levels deep", frame_.limits.includeFiles));
    const fs::path path = findIncludeFile(name);
    if (path.empty()) {
        const std::string why = whyNotFound(name);
        fail(at, why.starts_with("no such file")
                     ? fmt::format("cannot find include file '{}'", name)
                     : fmt::format("cannot include '{}': {}", name, why));
    }
    checkReadable(path, name, at);
    const SourceLoc callSite = loc(at);
    std::shared_ptr<const TokenizedFile> file;
    try {
        file = cache_.get(path);
    } catch (const SdlError& e) {
        // A lexer error in the include: its file has no cursor yet, so the
        // chain starts at this #include.
        std::vector<std::string> notes{fmt::format("in file included from {}:{}:{}",
                                                   callSite.file->path(), callSite.line,
                                                   callSite.column)};
        for (auto& note : includeChain(callSite)) notes.push_back(std::move(note));
        throw SdlError(e.loc(), e.message(), std::move(notes));
    }
    if (!file) fail(at, fmt::format("cannot read include file '{}'", path.string()));
    // A new symbol table for the file's #local identifiers.
    symbols_.push();
    cursors_.push_back({file, 0, CursorKind::File, symbols_.size() - 1, blocks_.size(), false});
    cursors_.back().callSite = callSite;
    ++includeDepth_;
}

double Reader::parseParenthesizedFloat() {
    expect(Sym::LParen, "'('");
    const Token at = peek();
    // The parentheses are the expression's own: comparisons, '&', '|' and
    // '? :' are allowed inside.
    const double v = toFloat(parseTernary(), at);
    expect(Sym::RParen, "')'");
    return v;
}

bool Reader::conditionExpression() {
    return std::fabs(parseParenthesizedFloat()) > kEpsilon;
}

bool Reader::conditionIfdef() {
    expect(Sym::LParen, "'('");
    const Token t = rawPeek();
    bool defined = false;
    if (t.kind == TokenKind::Word) {
        ++cursors_.back().pos;
        const Value* v = t.kw == Keyword::None ? lookup(t) : nullptr;
        defined = v != nullptr;
        // #ifdef (A[i]): whether that element has been set.
        if (v && std::holds_alternative<ArrayPtr>(*v) && peek().is(Sym::LBracket)) {
            const ArrayPtr array = std::get<ArrayPtr>(*v);
            defined = array->isSet(parseArrayIndex(*array, t));
        }
    } else {
        fail(t, fmt::format("expected an identifier, found {}", describeToken(t)));
    }
    expect(Sym::RParen, "')'");
    return defined;
}

bool Reader::conditionIfndef() {
    return !conditionIfdef();
}

void Reader::directiveIf(const Token& at, bool (Reader::*condition)()) {
    for (bool taken = (this->*condition)();; taken = conditionExpression()) {
        if (taken) {
            blocks_.push_back({BlockKind::If, loc(at)});
            return;
        }
        const Keyword found = skipBranch(true, false);
        if (found == Keyword::kw_else) {
            blocks_.push_back({BlockKind::If, loc(at)});
            blocks_.back().elseTaken = true;
            return;
        }
        if (found != Keyword::kw_elseif) return;  // #end
    }
}

void Reader::directiveElse(const Token& at) {
    if (!blocks_.empty() && blocks_.back().kind == BlockKind::Switch && at.kw == Keyword::kw_else)
        return;  // falling through into a switch's #else
    if (blocks_.empty() || blocks_.back().kind != BlockKind::If)
        fail(at, fmt::format("#{} without a matching #if", at.text));
    if (blocks_.back().elseTaken)
        fail(at, fmt::format("#{} after the #else of the #if at line {}", at.text,
                             blocks_.back().loc.line));
    // The taken branch ends here; skip every later branch. povray 3.7
    // skips a second #else here without complaint (measured), so this is a
    // warning, not an error.
    bool elseSeen = at.kw == Keyword::kw_else;
    for (Keyword found; (found = skipBranch(true, false)) != Keyword::kw_end;) {
        if (elseSeen) {
            const Cursor& c = cursors_.back();
            warn(window_.at(c.file, c.pos - 1),
                 fmt::format("#{} after the #else of the #if at line {} is never used",
                             keywordName(found), blocks_.back().loc.line));
        }
        elseSeen = found == Keyword::kw_else;
    }
    blocks_.pop_back();
}

void Reader::directiveEnd(const Token& at) {
    if (blocks_.empty() || blocks_.size() <= cursors_.back().blockCount)
        fail(at, "#end without a matching #if, #while, #for, #switch or #macro");
    Block& b = blocks_.back();
    switch (b.kind) {
        case BlockKind::If:
        case BlockKind::Switch:
            blocks_.pop_back();
            break;
        case BlockKind::While: {
            countIteration(b.loc);
            const size_t restart = b.restartPos;
            blocks_.pop_back();
            cursors_.back().pos = restart;  // re-runs the #while and its test
            break;
        }
        case BlockKind::For: {
            Value* var = symbols_.find(b.loopVar);
            if (!var || !std::holds_alternative<double>(*var))
                fail(at, fmt::format("#for loop variable '{}' is no longer a float", b.loopVar));
            const double before = std::get<double>(*var);
            const double value = before + b.loopStep;
            // A step too small for the variable's magnitude (or a NaN)
            // would repeat the same iteration forever.
            if (!(value != before))
                fail(at, fmt::format("#for step {} no longer changes the loop variable '{}' ({})",
                                     b.loopStep, b.loopVar, before));
            *var = value;
            const bool more =
                b.loopStep > 0 ? value <= b.loopEnd + kEpsilon : value >= b.loopEnd - kEpsilon;
            if (more) {
                countIteration(b.loc);
                cursors_.back().pos = b.restartPos;
            } else
                blocks_.pop_back();
            break;
        }
        case BlockKind::Macro: {
            const Cursor& c = cursors_.back();
            blocks_.resize(c.blockCount);
            symbols_.resize(c.scopeCount);
            cursors_.pop_back();
            break;
        }
    }
}

void Reader::directiveWhile(const Token& at, size_t hashPos) {
    if (conditionExpression()) {
        Block b{BlockKind::While, loc(at)};
        b.restartPos = hashPos;
        blocks_.push_back(b);
    } else {
        skipBranch(false, false);
    }
}

void Reader::directiveFor(const Token& at) {
    expect(Sym::LParen, "'('");
    const std::string var = expectIdentifier();
    expect(Sym::Comma, "','");
    const double start = parseFloat();
    expect(Sym::Comma, "','");
    const double end = parseFloat();
    double step = 1;
    if (accept(Sym::Comma)) step = parseFloat();
    expect(Sym::RParen, "')'");
    if (step == 0) fail(at, "#for step must not be zero");
    symbols_.declare(var, start, true);
    const bool run = step > 0 ? start <= end + kEpsilon : start >= end - kEpsilon;
    if (!run) {
        skipBranch(false, false);
        return;
    }
    Block b{BlockKind::For, loc(at)};
    b.restartPos = cursors_.back().pos;
    b.loopVar = var;
    b.loopEnd = end;
    b.loopStep = step;
    blocks_.push_back(b);
}

void Reader::directiveSwitch(const Token& at) {
    const double value = parseParenthesizedFloat();
    Block b{BlockKind::Switch, loc(at)};
    b.switchValue = value;
    // Find the first label that matches; its body runs until #break.
    for (;;) {
        const Keyword found = skipBranch(false, true);
        if (found == Keyword::kw_end) return;
        if (found == Keyword::kw_else) break;
        if (found == Keyword::kw_break) continue;
        bool match;
        if (found == Keyword::kw_case) {
            match = std::fabs(parseParenthesizedFloat() - value) < kEpsilon;
        } else {
            expect(Sym::LParen, "'('");
            const double lo = parseFloat();
            expect(Sym::Comma, "','");
            const double hi = parseFloat();
            expect(Sym::RParen, "')'");
            match = value >= lo && value <= hi;
        }
        if (match) break;
    }
    blocks_.push_back(b);
}

void Reader::directiveBreak(const Token& at) {
    // Leave the innermost loop, switch or macro; any #if blocks inside it
    // are left too.
    size_t i = blocks_.size();
    while (i > cursors_.back().blockCount && blocks_[i - 1].kind == BlockKind::If) --i;
    if (i == cursors_.back().blockCount && cursors_.back().kind != CursorKind::Macro) {
        // #break outside anything breakable is ignored, as POV-Ray does.
        (void)at;
        return;
    }
    const size_t ends = blocks_.size() - i + 1;
    for (size_t k = 0; k < ends; ++k) skipBranch(false, false);
    const Block target = blocks_[i - 1];
    blocks_.resize(i - 1);
    if (target.kind == BlockKind::Macro) {
        const Cursor& c = cursors_.back();
        blocks_.resize(c.blockCount);
        symbols_.resize(c.scopeCount);
        cursors_.pop_back();
    }
}

void Reader::directiveMacro(const Token& at) {
    auto macro = std::make_shared<Macro>();
    macro->name = expectIdentifier();
    macro->loc = loc(at);
    expect(Sym::LParen, "'('");
    if (!peek().is(Sym::RParen)) {
        do {
            macro->params.push_back(expectIdentifier());
            // povray accepts a comma before the ')' (shapes3.inc's
            // Rounded_Tube) and none between two names (its
            // Half_Hollowed_Rounded_Cylinder2).
        } while ((accept(Sym::Comma) && !peek().is(Sym::RParen)) || rawPeek().isIdentifier());
    }
    expect(Sym::RParen, "')'");
    macro->file = cursors_.back().file;
    macro->bodyStart = cursors_.back().pos;
    // The body runs at each call; now it is only skipped.
    const Keyword found = skipBranch(false, false);
    (void)found;
    symbols_.declare(macro->name, MacroPtr(macro), false);
}

void Reader::invokeMacro(const Token& nameToken, const Macro& macro) {
    // Cursors are the scene file, the open include files and the macro
    // calls in progress.
    const size_t macroCalls = cursors_.size() - 1 - static_cast<size_t>(includeDepth_);
    if (macroCalls >= static_cast<size_t>(frame_.limits.macroCalls))
        fail(nameToken,
             fmt::format("macro calls nested too deeply (more than {})", frame_.limits.macroCalls));
    countIteration(loc(nameToken));
    SymbolTable::Scope args;
    expectAfter(Sym::LParen, "'('", macro.name);
    size_t count = 0;
    // The commas between arguments are optional in povray (`M(<1,0,0> .5)`),
    // and a trailing one is ignored (`M(1, 2,)`).
    while (!peek().is(Sym::RParen)) {
        Value v = bareIdentifierArgument();
        if (std::holds_alternative<std::monostate>(v)) v = parseRValue();
        if (count < macro.params.size()) args[macro.params[count]] = std::move(v);
        ++count;
        accept(Sym::Comma);
    }
    expect(Sym::RParen, "')'");
    if (count != macro.params.size())
        fail(nameToken,
             fmt::format("macro '{}' takes {} parameter{}, {} given", macro.name,
                         macro.params.size(), macro.params.size() == 1 ? "" : "s", count));
    const SourceLoc callSite = loc(nameToken);
    cursors_.push_back(
        {macro.file, macro.bodyStart, CursorKind::Macro, symbols_.size(), blocks_.size(), false});
    cursors_.back().callSite = callSite;
    cursors_.back().macroName = macro.name;
    symbols_.push(std::move(args));
    blocks_.push_back({BlockKind::Macro, macro.loc});
}

Value Reader::bareIdentifierArgument() {
    // A lone identifier (followed by ',' or ')') is passed by reference.
    const Cursor& c = cursors_.back();
    const Token& t = rawPeek();
    if (!t.isIdentifier() || c.pos + 1 >= c.file->size()) return {};
    const Token& after = window_.at(c.file, c.pos + 1);
    if (!after.is(Sym::Comma) && !after.is(Sym::RParen)) return {};
    const std::string name(t.text);
    // Find the scope holding it (following an alias of an outer macro).
    const std::optional<IdentifierAlias> found = symbols_.aliasFor(name);
    if (!found) return {};  // a macro call, not a reference
    const IdentifierAlias& alias = *found;
    if (alias.scope == symbols_.size())
        fail(t,
             fmt::format("cannot pass the undeclared identifier '{}' to a macro; declare it first",
                         name));
    ++cursors_.back().pos;
    return alias;
}

void Reader::directiveMessage(Stream stream) {
    const std::string text = parseString();
    messages_.message(stream, text);
}

Keyword Reader::skipBranch(bool stopAtElse, bool stopAtCase) {
    const SourceLoc start = blocks_.empty() ? SourceLoc{} : blocks_.back().loc;
    Cursor& c = cursors_.back();
    int depth = 0;
    for (;;) {
        const Token& t = window_.at(c.file, c.pos);
        if (t.kind == TokenKind::End)
            throw SdlError(start.file ? start : c.file->locOf(t),
                           "missing #end: the file ends inside this directive");
        ++c.pos;
        if (!t.is(Sym::Hash)) continue;
        const Token& w = window_.at(c.file, c.pos);
        if (w.kind != TokenKind::Word) continue;
        switch (w.kw) {
            case Keyword::kw_if:
            case Keyword::kw_ifdef:
            case Keyword::kw_ifndef:
            case Keyword::kw_while:
            case Keyword::kw_for:
            case Keyword::kw_switch:
            case Keyword::kw_macro:
                ++depth;
                break;
            case Keyword::kw_end:
                if (depth == 0) {
                    ++c.pos;
                    return Keyword::kw_end;
                }
                --depth;
                break;
            case Keyword::kw_else:
            case Keyword::kw_elseif:
                if (depth == 0 && (stopAtElse || (stopAtCase && w.kw == Keyword::kw_else))) {
                    ++c.pos;
                    return w.kw;
                }
                break;
            case Keyword::kw_case:
            case Keyword::kw_range:
            case Keyword::kw_break:
                if (depth == 0 && stopAtCase) {
                    ++c.pos;
                    return w.kw;
                }
                break;
            default:
                break;
        }
    }
}

}  // namespace frameray::sdl
