// POV-Ray's shell-outs: Pre_Scene/Pre_Frame/Post_Frame/Post_Scene/
// User_Abort/Fatal_Error_Command, with their %-substitutions, and what the
// *_Return options say to do with the command's exit code.
#pragma once

#include <string>

#include "options/render_options.h"

namespace frameray::anim {

// What the run does after a shell-out.
enum class HookAction { Continue, SkipFrame, SkipAll, Quit, UserAbort, Fatal };
inline constexpr const char* kHookActionNames[] = {"continue", "skip_frame", "skip_all",
                                                   "quit",     "user_abort", "fatal"};

struct HookValues {
    std::string output;         // %o
    std::string scene;          // %s: scene file name without folder and extension
    int frame = 0;              // %n
    double clock = 0;           // %k
    int width = 0, height = 0;  // %w %h
};

// The command with %o %s %n %k %h %w %% replaced.
std::string substituteCommand(const std::string& command, const HookValues& values);

// The action a *_Return value asks for given the command's exit code: a
// letter (I S A Q U F) acts on a non-zero code, after '-' or '!' on zero.
HookAction returnAction(const std::string& actionText, int exitCode);

// Empty when the options may run their shell-outs: none is set, or
// Allow_Shell_Commands is on. Otherwise the error naming the first
// command set and the option that would allow it.
std::string shellCommandRefusal(const options::RenderOptions& options);

// Runs the hook's command through /bin/sh (nothing when it has none) and
// returns what to do next.
// `exitCode`, when given, receives the command's exit status (128 + the
// signal for a command killed by one; -1 when no shell could be started).
HookAction runHook(const options::ShellCommand& hook, const HookValues& values,
                   int* exitCode = nullptr);

}  // namespace frameray::anim
