#!/usr/bin/env python3
"""Photon maps shot once and reused across frames (save_file / load_file).

    photons_reuse_test.py FRAMERAY SCENE WORKDIR

Renders SCENE (tests/anim/photons/reuse.pov) as a three-frame animation
twice, from WORKDIR (photon files are named from the working folder):
  - shooting in every frame;
  - with Declare=Reuse=1: frame 1 shoots and writes reuse.ph, frames 2 and 3
    load it (two frames in flight, two threads).
The frames must be byte-identical, sequence.json must say frames 2 and 3
loaded their maps (nothing shot) with as many photons as frame 1 stored,
and a load_file of a povray photon file must stop with a message.
"""
import json
import os
import shutil
import subprocess
import sys


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


def render(frameray, scene, work, name, extra, expect_ok=True):
    out = os.path.join(work, name)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    proc = subprocess.run([frameray, scene, "+W96", "+H72", "+KFI1", "+KFF3", "+WT2",
                           "Frames_In_Flight=2", "+O" + out + "/"] + extra,
                          capture_output=True, text=True, timeout=240, cwd=work,
                          env=dict(os.environ, POVINI=os.devnull))
    if not expect_ok:
        return proc
    if proc.returncode != 0:
        fail(f"{name}: exit {proc.returncode}\n{proc.stderr}")
    images = {}
    for f in sorted(os.listdir(out)):
        if f.endswith(".png"):
            with open(os.path.join(out, f), "rb") as handle:
                images[f] = handle.read()
    with open(os.path.join(out, "sequence.json")) as handle:
        frames = json.load(handle)["frames"]
    return images, [frame["stats"].get("photons") for frame in frames]


def main():
    frameray, scene, work = sys.argv[1:4]
    work = os.path.abspath(work)
    os.makedirs(work, exist_ok=True)
    ph = os.path.join(work, "reuse.ph")
    if os.path.exists(ph):
        os.remove(ph)
    every, every_photons = render(frameray, scene, work, "every", [])
    if os.path.exists(ph):
        fail("a run without Reuse wrote reuse.ph")
    once, once_photons = render(frameray, scene, work, "once", ["Declare=Reuse=1"])
    if not os.path.exists(ph):
        fail("frame 1 did not write reuse.ph (save_file)")
    if len(every) != 3 or sorted(every) != sorted(once):
        fail(f"frames differ: {sorted(every)} vs {sorted(once)}")
    for name in every:
        if every[name] != once[name]:
            fail(f"{name}: the frame that loaded its photons differs from the one that shot them")
    first = once_photons[0]
    if not first or first["loaded"] or first["shot"] <= 0:
        fail(f"frame 1 should shoot: {first}")
    for p in once_photons[1:]:
        if not p or not p["loaded"] or p["shot"] != 0 or p["stored"] != first["stored"] \
                or p["gather_radius"] != first["gather_radius"]:
            fail(f"a later frame should load frame 1's map: {p} (frame 1: {first})")
    for p in every_photons:
        if p["loaded"] or p["stored"] != first["stored"]:
            fail(f"shooting in every frame: {p}")
    # povray's photon file (its first bytes: the photon count) is refused.
    with open(ph, "wb") as handle:
        handle.write(bytes([0x4e, 0x0a, 0, 0, 0x06, 0x44, 0x02, 0xc0]) + bytes(40))
    shutil.copy(scene, os.path.join(work, "povrays.pov"))
    with open(os.path.join(work, "povrays.pov"), "a") as handle:
        handle.write('global_settings { photons { load_file "reuse.ph" } }\n')
    proc = render(frameray, os.path.join(work, "povrays.pov"), work, "povrays", [],
                  expect_ok=False)
    if proc.returncode == 0 or "is not a frameray photon map" not in proc.stderr:
        fail(f"povray's photon file: exit {proc.returncode}\n{proc.stderr}")
    print("ok:", first, once_photons[1])


main()
