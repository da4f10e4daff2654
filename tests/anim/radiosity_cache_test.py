#!/usr/bin/env python3
"""Radiosity across frames: Radiosity_Stable and the cache files (issue 26).

    radiosity_cache_test.py FRAMERAY SCENE_DIR WORKDIR

SCENE_DIR holds tests/bench/radiosity's flicker.pov/.ini (a static room,
the camera one pixel further right each frame). Checks:
  - Radiosity_Stable=on gives byte-identical frames with 1 thread / 1 frame
    in flight and 2 threads / 3 frames in flight;
  - its frames after the first shoot far fewer radiosity rays than the first
    (they start from the first frame's cache; sequence.json);
  - Radiosity_To_File writes the cache file (Radiosity_File_Name), a run
    with Radiosity_From_File reads it and shoots fewer radiosity rays;
  - a cache file in povray's format is refused with a message, exit 1.
"""
import json
import os
import shutil
import subprocess
import sys

from sequence_fixture import fail


def run(frameray, work, name, switches, expect_ok=True):
    out = os.path.join(work, name)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    env = dict(os.environ, POVINI=os.devnull)
    proc = subprocess.run([frameray, os.path.join(work, "flicker.ini"), "+W48", "+H36",
                           "+O" + out + "/", *switches],
                          cwd=work, env=env, capture_output=True, text=True, timeout=240)
    if expect_ok and proc.returncode != 0:
        fail(f"{switches}: exit {proc.returncode}\n{proc.stderr}")
    return out, proc


def frames(out):
    result = {}
    for name in sorted(os.listdir(out)):
        if name.endswith(".png"):
            with open(os.path.join(out, name), "rb") as f:
                result[name] = f.read()
    return result


def radiosity_rays(out):
    with open(os.path.join(out, "sequence.json")) as f:
        return [frame["rays"]["radiosity"] for frame in json.load(f)["frames"]]


def main():
    frameray, scene_dir, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    for name in ("flicker.pov", "flicker.ini"):
        shutil.copy(os.path.join(scene_dir, name), work)
    with open(os.path.join(work, "flicker.ini"), "a") as f:
        f.write("Final_Frame=4\n")

    serial, _ = run(frameray, work, "serial", ["+WT1", "+WF1", "Radiosity_Stable=on"])
    overlap, _ = run(frameray, work, "overlap", ["+WT2", "+WF3", "Radiosity_Stable=on"])
    a, b = frames(serial), frames(overlap)
    if len(a) != 4 or a != b:
        fail(f"Radiosity_Stable frames differ between 1 and 2 threads: {sorted(a)} {sorted(b)}")
    rays = radiosity_rays(serial)
    if not all(r * 2 < rays[0] for r in rays[1:]):
        fail(f"later frames should start from the first frame's cache: radiosity rays {rays}")

    cache = os.path.join(work, "room.rca")
    first, _ = run(frameray, work, "to_file",
                   ["+WT2", "Final_Frame=2", "+RFO", "Radiosity_File_Name=" + cache])
    with open(cache) as f:
        if f.readline().strip() != "frameray radiosity cache 3" or len(f.readlines()) < 10:
            fail("Radiosity_To_File wrote no cache")
    again, _ = run(frameray, work, "from_file",
                   ["+WT2", "Final_Frame=2", "+RFI", "Radiosity_File_Name=" + cache])
    if not radiosity_rays(again)[0] * 2 < radiosity_rays(first)[0]:
        fail(f"Radiosity_From_File: {radiosity_rays(again)} vs {radiosity_rays(first)} rays")

    foreign = os.path.join(work, "pov.rca")
    with open(foreign, "w") as f:
        f.write("C2\t-1.29\t-0.9\t0.76\t7ffe7f\t0.0985\t0.0988\t0.1161\t0.96\t0.24\tcfc4c6\n")
    _, proc = run(frameray, work, "foreign",
                  ["Final_Frame=1", "+RFI", "Radiosity_File_Name=" + foreign], expect_ok=False)
    if proc.returncode != 1 or "not a frameray radiosity cache file" not in proc.stderr:
        fail(f"a povray cache file: exit {proc.returncode}\n{proc.stderr}")
    print("ok")


if __name__ == "__main__":
    main()
