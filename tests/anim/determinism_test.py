#!/usr/bin/env python3
"""The frame scheduler gives the same images whatever the threads.

    determinism_test.py FRAMERAY REPO_ROOT WORKDIR

Renders the demo animation (ini/demo.ini, smaller, its scene printing a
#debug and a #warning line per frame) with
  Work_Threads=1 Frames_In_Flight=1   (frame after frame, one thread)
  Work_Threads=2 Frames_In_Flight=3   (frames overlapping)
  Work_Threads=2 Frames_In_Flight=24  (every frame in flight at once)
Every image must be byte-identical across the settings; the frame logs and
the console must read the same apart from timings (the scheduler prints a
frame's messages only after every earlier frame's). Each run must write
sequence.json beside the frames with per-frame ray counts and times.
"""
import json
import os
import re
import shutil
import subprocess
import sys

from sequence_fixture import fail

SETTINGS = [("+WT1", "+WF1"), ("+WT2", "+WF3"), ("Work_Threads=2", "Frames_In_Flight=24")]
TIMING = re.compile(r"\d+\.\d+ s")


def run(frameray, root, scene, out, switches):
    shutil.rmtree(out, ignore_errors=True)
    proc = subprocess.run([frameray, "ini/demo.ini", "+I" + scene, "+W160", "+H120", "+O" + out + "/", *switches],
                          cwd=root, capture_output=True, text=True, timeout=240)
    if proc.returncode != 0:
        fail(f"{switches}: exit {proc.returncode}\n{proc.stderr}")
    files = {}
    for name in sorted(os.listdir(out)):
        path = os.path.join(out, name)
        if name.endswith(".png"):
            with open(path, "rb") as f:
                files[name] = f.read()
        elif name.endswith(".frameray.log"):
            continue  # the run log records times, threads and pids: not the frames' content
        elif name.endswith(".log"):
            with open(path) as f:
                files[name] = TIMING.sub("<t>", f.read()).replace(out, "<out>")
    # Progress lines (one per finished frame when stderr is not a terminal)
    # and the summary table at the end carry times and the settings; the
    # rest of the console must read the same.
    text = proc.stderr
    if "progress: frame 24 - 24 of 24 done" not in text or "frameray summary" not in text:
        fail(f"{switches}: no progress lines or summary on the console:\n{text}")
    text = text[:text.index("frameray summary")]
    text = "".join(line for line in text.splitlines(True) if not line.startswith("progress: "))
    console = TIMING.sub("<t>", text).replace(out, "<out>")
    return files, console, os.path.join(out, "sequence.json")


def check_statistics(path, switches, frames):
    if not os.path.exists(path):
        fail(f"{switches}: no {path}")
    with open(path) as f:
        stats = json.load(f)
    for key in ("frames", "rays", "parse_seconds", "render_seconds", "wall_seconds", "cpu_seconds",
                "frames_in_flight", "work_threads"):
        if key not in stats:
            fail(f"{switches}: sequence.json has no '{key}'")
    if len(stats["frames"]) != frames:
        fail(f"{switches}: sequence.json lists {len(stats['frames'])} frames, expected {frames}")
    total = {"camera": 0, "shadow": 0, "reflection": 0, "refraction": 0, "transmission": 0,
             "media_samples": 0, "radiosity": 0}
    for i, frame in enumerate(stats["frames"]):
        for key in ("number", "rays", "parse_seconds", "render_seconds"):
            if key not in frame:
                fail(f"{switches}: sequence.json frame {i} has no '{key}'")
        for key in total:
            if key not in frame["rays"]:
                fail(f"{switches}: sequence.json frame {i} rays have no '{key}'")
            total[key] += frame["rays"][key]
        if frame["number"] != i + 1:
            fail(f"{switches}: sequence.json frame {i} is number {frame['number']}")
        stats_keys = ("rays", "intersection_tests", "parse_seconds", "render_seconds")
        if any(key not in frame.get("stats", {}) for key in stats_keys):
            fail(f"{switches}: sequence.json frame {i} has no 'stats' with {stats_keys}")
        if frame["stats"]["rays"] != frame["rays"] or not frame["stats"]["intersection_tests"]:
            fail(f"{switches}: sequence.json frame {i} stats: {frame['stats']}")
        if frame["rays"]["camera"] != 160 * 120:
            fail(f"{switches}: frame {i + 1} has {frame['rays']['camera']} camera rays")
    if stats["rays"] != total:
        fail(f"{switches}: summed rays {stats['rays']} != {total}")
    return stats


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    frameray, root, work = os.path.abspath(sys.argv[1]), sys.argv[2], os.path.abspath(sys.argv[3])
    os.makedirs(work, exist_ok=True)
    # The demo scene, telling on the console which frame it parses.
    scene = os.path.join(work, "demo.pov")
    with open(os.path.join(root, "examples", "demo", "demo.pov")) as f:
        demo = f.read()
    with open(scene, "w") as f:
        f.write('#debug concat("parsing frame ", str(frame_number, 0, 0), "\\n")\n'
                '#warning concat("warning of frame ", str(frame_number, 0, 0))\n' + demo)
    reference = None
    for i, switches in enumerate(SETTINGS):
        files, console, stats_path = run(frameray, root, scene, os.path.join(work, f"run{i}"), switches)
        pngs = [n for n in files if n.endswith(".png")]
        if len(pngs) != 24:
            fail(f"{switches}: {len(pngs)} frames written, expected 24")
        stats = check_statistics(stats_path, switches, 24)
        # With more than one frame in flight the first frame is measured
        # alone and bounds the others by memory.
        wanted = int(switches[1].split("=")[-1].lstrip("+WF"))
        if wanted > 1 and not (stats["frame_memory_estimate_bytes"] > 0 and 1 <= stats["frames_in_flight"] <= wanted):
            fail(f"{switches}: no memory estimate or frames in flight out of range: "
                 f"{stats['frame_memory_estimate_bytes']}, {stats['frames_in_flight']}")
        if reference is None:
            reference = (switches, files, console, stats["rays"])
            continue
        ref_switches, ref_files, ref_console, ref_rays = reference
        if sorted(files) != sorted(ref_files):
            fail(f"{switches} wrote {sorted(files)}, {ref_switches} wrote {sorted(ref_files)}")
        for name in ref_files:
            if files[name] != ref_files[name]:
                fail(f"{name} differs between {ref_switches} and {switches}")
        if console.count("parsing frame") != 24 or console.count("warning of frame") != 24:
            fail(f"{switches}: the scene's messages are missing from the console:\n{console}")
        if console != ref_console:
            fail(f"the console differs between {ref_switches} and {switches}:\n{ref_console}\n---\n{console}")
        if stats["rays"] != ref_rays:
            fail(f"ray counts differ between {ref_switches} and {switches}")
        print(f"{switches}: 24 frames identical to {ref_switches}")
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
