#include "anim/hooks.h"

#include <fmt/format.h>
#include <sys/wait.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace frameray::anim {

namespace {

// Where a position in a /bin/sh command is: outside quotes, or inside
// '...' or "...".
enum class Quoting { None, Single, Double };

bool plainWord(const std::string& text) {
    if (text.empty()) return false;
    for (const char c : text)
        if (!std::isalnum(static_cast<unsigned char>(c)) &&
            std::string_view("_./+-,:=@").find(c) == std::string_view::npos)
            return false;
    return true;
}

// `text` (a file or scene name, which the scene's INI file may choose)
// as the shell reads it back literally where it is inserted: a file named
// y$(touch x).png must not run touch.
std::string shellQuoted(const std::string& text, Quoting where) {
    std::string out;
    switch (where) {
        case Quoting::None:
            if (plainWord(text)) return text;
            out = "'";
            for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
            return out + "'";
        case Quoting::Single:
            for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
            return out;
        case Quoting::Double:
            for (const char c : text) {
                if (c == '\\' || c == '"' || c == '$' || c == '`') out += '\\';
                out += c;
            }
            return out;
    }
    return out;
}

}  // namespace

std::string substituteCommand(const std::string& command, const HookValues& v) {
    std::string out;
    Quoting quoting = Quoting::None;
    for (size_t i = 0; i < command.size(); ++i) {
        const char c = command[i];
        if (c != '%' || i + 1 == command.size()) {
            out += c;
            // Follow the shell's quoting, so that a substitution is quoted
            // for where it lands.
            if (c == '\\' && quoting != Quoting::Single && i + 1 < command.size()) {
                out += command[++i];
            } else if (c == '\'' && quoting != Quoting::Double) {
                quoting = quoting == Quoting::Single ? Quoting::None : Quoting::Single;
            } else if (c == '"' && quoting != Quoting::Single) {
                quoting = quoting == Quoting::Double ? Quoting::None : Quoting::Double;
            }
            continue;
        }
        const char letter =
            static_cast<char>(std::tolower(static_cast<unsigned char>(command[++i])));
        switch (letter) {
            case 'o':
                out += shellQuoted(v.output, quoting);
                break;
            case 's':
                out += shellQuoted(v.scene, quoting);
                break;
            case 'n':
                out += std::to_string(v.frame);
                break;
            case 'k':
                out += fmt::format("{:g}", v.clock);
                break;
            case 'h':
                out += std::to_string(v.height);
                break;
            case 'w':
                out += std::to_string(v.width);
                break;
            case '%':
                out += '%';
                break;
            default:
                out += '%';
                out += command[i];
                break;
        }
    }
    return out;
}

HookAction returnAction(const std::string& text, int exitCode) {
    std::string_view t(text);
    bool onZero = false;
    if (!t.empty() && (t[0] == '-' || t[0] == '!')) {
        onZero = true;
        t.remove_prefix(1);
    }
    if (t.empty()) return HookAction::Continue;
    const bool triggered = onZero ? exitCode == 0 : exitCode != 0;
    if (!triggered) return HookAction::Continue;
    switch (std::toupper(static_cast<unsigned char>(t[0]))) {
        case 'S':
            return HookAction::SkipFrame;
        case 'A':
            return HookAction::SkipAll;
        case 'Q':
            return HookAction::Quit;
        case 'U':
            return HookAction::UserAbort;
        case 'F':
            return HookAction::Fatal;
        default:
            return HookAction::Continue;
    }
}

std::string shellCommandRefusal(const options::RenderOptions& o) {
    if (o.allowShellCommands) return {};
    // In the order of options::ShellHook.
    static constexpr const char* kNames[options::kShellHooks] = {
        "Pre_Scene_Command",  "Pre_Frame_Command",  "Post_Frame_Command",
        "Post_Scene_Command", "User_Abort_Command", "Fatal_Error_Command"};
    for (int i = 0; i < options::kShellHooks; ++i) {
        const std::string& command = o.commands[static_cast<size_t>(i)].command;
        if (command.empty()) continue;
        return fmt::format(
            "{} '{}' is refused: shell commands do not run unless Allow_Shell_Commands=on is given "
            "(on the "
            "command line or in frameray.conf)",
            kNames[i], command);
    }
    return {};
}

HookAction runHook(const options::ShellCommand& hook, const HookValues& values, int* exitCode) {
    if (hook.command.empty()) return HookAction::Continue;
    const std::string cmd = substituteCommand(hook.command, values);
    std::fflush(nullptr);
    const int status = std::system(cmd.c_str());
    int code = status;
    if (status != -1 && WIFEXITED(status))
        code = WEXITSTATUS(status);
    else if (status != -1)
        code = 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    if (exitCode) *exitCode = code;
    return returnAction(hook.action, code);
}

}  // namespace frameray::anim
