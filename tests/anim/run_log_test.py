#!/usr/bin/env python3
"""frameray's run log beside an animation's frames (NAME.frameray.log).

    run_log_test.py FRAMERAY WORKDIR

1. Log_Format=json: every line parses as JSON with time, level and event;
   one `written` event per frame (frames 1..5, each with its clock and
   file), framed by `run_start` and `run_end`.
2. A +C run appends: the first run's lines stay, and one `kept` event per
   frame follows.
3. A frame that fails leaves a `failed` event (level error) with the reason.
4. Log_Level=debug adds `parse_done` and `render_done` for every frame;
   Log_Level=off writes no log; a still image writes none.
5. Hooks and option warnings: a Post_Frame_Command leaves one `hook` event
   per frame (its exit code and the action taken), a failing Post_Scene
   command a warning-level one; an option povray 3.7 ignores leaves an
   `option_warning` event.
"""
import json
import os
import subprocess
import sys

from sequence_fixture import fail, make_sequence

FRAMES = 5

SCENE = """#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -4> look_at 0 }
light_source { <3, 5, -4> rgb 1 }
#if (frame_number = FailAt) #error "frame failed on purpose" #end
sphere { <-1 + 2 * clock, 0.5, 0>, 0.6 pigment { rgb <0.2, 0.6, 1> } }
"""


def events(path):
    if not os.path.exists(path):
        fail("no run log %s" % path)
    out = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            try:
                e = json.loads(line)
            except ValueError as err:
                fail("line %d of the run log is not JSON (%s): %r" % (number, err, line))
            for key in ("time", "level", "event"):
                if key not in e:
                    fail("line %d has no %r: %r" % (number, key, line))
            out.append(e)
    return out


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    frameray = os.path.abspath(sys.argv[1])
    work = os.path.abspath(sys.argv[2])
    ini, env = make_sequence(
        work, "orbit", SCENE,
        "Width=64\nHeight=48\nInitial_Frame=1\nFinal_Frame=%d\nDeclare=FailAt=-1\n"
        "Log_Format=json\n" % FRAMES)
    log = os.path.join(work, "orbit.frameray.log")

    def run(*extra):
        cmd = [frameray, ini] + list(extra)
        r = subprocess.run(cmd, cwd=work, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        return r.returncode, r.stdout.decode(errors="replace")

    # 1. One written event per frame.
    code, out = run("-V")
    if code != 0:
        fail("the first run failed:\n" + out)
    first = events(log)
    kinds = [e["event"] for e in first]
    if kinds[0] != "run_start" or kinds[-1] != "run_end":
        fail("the run log does not start with run_start and end with run_end: %s" % kinds)
    written = [e for e in first if e["event"] == "written"]
    if [e["frame"] for e in written] != list(range(1, FRAMES + 1)):
        fail("written events are not one per frame in order: %s" % [e.get("frame") for e in written])
    for e in written:
        expected_clock = (e["frame"] - 1) / (FRAMES - 1)
        if abs(e["clock"] - expected_clock) > 1e-12 or e["file"] != "orbit%d.png" % e["frame"]:
            fail("written event with a wrong clock or file: %s" % e)
        if e["camera_rays"] < 64 * 48 or e["bytes"] <= 0:
            fail("written event without its figures: %s" % e)
    if first[-1]["outcome"] != "finished" or first[-1]["frames_finished"] != FRAMES:
        fail("run_end does not say the run finished: %s" % first[-1])

    # 2. +C appends kept events.
    code, out = run("-V", "+C")
    if code != 0:
        fail("the +C run failed:\n" + out)
    both = events(log)
    if both[:len(first)] != first:
        fail("the +C run did not keep the first run's lines")
    kept = [e["frame"] for e in both[len(first):] if e["event"] == "kept"]
    if kept != list(range(1, FRAMES + 1)):
        fail("the +C run logged kept frames %s" % kept)

    # 3. A failing frame.
    os.remove(log)
    code, out = run("-V", "Declare=FailAt=3")
    if code == 0:
        fail("a run with a failing frame exited 0")
    failed = [e for e in events(log) if e["event"] == "failed"]
    if len(failed) != 1 or failed[0]["frame"] != 3 or failed[0]["level"] != "error" \
            or "frame failed on purpose" not in failed[0]["reason"]:
        fail("no failed event for frame 3 with its reason: %s" % failed)

    # 4. Levels, and no log where there is no sequence.
    os.remove(log)
    code, out = run("-V", "Log_Level=debug")
    if code != 0:
        fail("the debug run failed:\n" + out)
    debug = events(log)
    for kind in ("parse_done", "render_done"):
        frames = sorted(e["frame"] for e in debug if e["event"] == kind)
        if frames != list(range(1, FRAMES + 1)):
            fail("Log_Level=debug: %s events for frames %s" % (kind, frames))
    os.remove(log)
    code, out = run("-V", "Log_Level=off")
    if code != 0 or os.path.exists(log):
        fail("Log_Level=off: exit %d, log %s" % (code, "written" if os.path.exists(log) else "absent"))
    code, out = run("-V", "Final_Frame=1", "+Ostill.png")
    if code != 0 or os.path.exists(log):
        fail("a still wrote a run log (exit %d)" % code)
    # 5. Hooks and option warnings (the still above left no log).
    code, out = run("-V", "Allow_Shell_Commands=on", "Post_Frame_Command=true",
                    "Post_Scene_Command=exit 3", "Light_Buffer=on")
    if code != 0:
        fail("the run with hooks failed:\n" + out)
    hooked = events(log)
    post_frame = [e for e in hooked if e["event"] == "hook" and e["hook"] == "post_frame"]
    if sorted(e["frame"] for e in post_frame) != list(range(1, FRAMES + 1)) or any(
            e["exit_code"] != 0 or e["action"] != "continue" or e["level"] != "info"
            for e in post_frame):
        fail("post_frame hook events: %s" % post_frame)
    post_scene = [e for e in hooked if e["event"] == "hook" and e["hook"] == "post_scene"]
    if len(post_scene) != 1 or post_scene[0]["exit_code"] != 3 or post_scene[0]["level"] != "warning":
        fail("post_scene hook event: %s" % post_scene)
    if not any(e["event"] == "option_warning" and "Light_Buffer" in e["message"] for e in hooked):
        fail("no option_warning event for Light_Buffer: %s" % [e["event"] for e in hooked])
    print("run log: %d lines JSON, %d written, %d kept, failed and debug events as expected"
          % (len(both), len(written), len(kept)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
