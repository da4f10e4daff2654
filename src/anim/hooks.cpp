#include "anim/hooks.h"

#include <fmt/format.h>
#include <sys/wait.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>

namespace frameray::anim {

std::string substituteCommand(const std::string& command, const HookValues& v) {
    std::string out;
    for (size_t i = 0; i < command.size(); ++i) {
        if (command[i] != '%' || i + 1 == command.size()) {
            out += command[i];
            continue;
        }
        const char c = static_cast<char>(std::tolower(static_cast<unsigned char>(command[++i])));
        switch (c) {
            case 'o':
                out += v.output;
                break;
            case 's':
                out += v.scene;
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

HookAction runHook(const options::ShellCommand& hook, const HookValues& values) {
    if (hook.command.empty()) return HookAction::Continue;
    const std::string cmd = substituteCommand(hook.command, values);
    std::fflush(nullptr);
    const int status = std::system(cmd.c_str());
    int code = status;
    if (status != -1 && WIFEXITED(status))
        code = WEXITSTATUS(status);
    else if (status != -1)
        code = 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    return returnAction(hook.action, code);
}

}  // namespace frameray::anim
