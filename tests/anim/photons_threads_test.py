#!/usr/bin/env python3
"""Photon shooting gives the same image whatever the thread count.

    photons_threads_test.py FRAMERAY SCENE WORKDIR

Renders SCENE (jittered photons, an area light shooting from its grid,
dispersion, a mirror) as a two-frame animation at Work_Threads 1 and 2:
the frames must be byte-identical, and sequence.json must report the photon
map of every frame (photons shot, stored, memory), the same in both runs.
"""
import json
import os
import shutil
import subprocess
import sys


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


def render(frameray, scene, out, threads):
    shutil.rmtree(out, ignore_errors=True)
    proc = subprocess.run([frameray, scene, "+W160", "+H120", "+KFI1", "+KFF2", "+WT" + str(threads),
                           "+O" + out + "/"], capture_output=True, text=True, timeout=240,
                          env=dict(os.environ, POVINI="/dev/null"))
    if proc.returncode != 0:
        fail(f"+WT{threads}: exit {proc.returncode}\n{proc.stderr}")
    images = {}
    for name in sorted(os.listdir(out)):
        if name.endswith(".png"):
            with open(os.path.join(out, name), "rb") as f:
                images[name] = f.read()
    with open(os.path.join(out, "sequence.json")) as f:
        frames = json.load(f)["frames"]
    photons = [frame["stats"].get("photons") for frame in frames]
    return images, photons


def main():
    frameray, scene, work = sys.argv[1:4]
    one, photons_one = render(frameray, scene, os.path.join(work, "wt1"), 1)
    two, photons_two = render(frameray, scene, os.path.join(work, "wt2"), 2)
    if len(one) != 2 or sorted(one) != sorted(two):
        fail(f"frames differ: {sorted(one)} vs {sorted(two)}")
    for name in one:
        if one[name] != two[name]:
            fail(f"{name} differs between +WT1 and +WT2")
    for p in photons_one:
        if not p or p["shot"] <= 0 or p["stored"] <= 0 or p["memory_bytes"] <= 0:
            fail(f"sequence.json: no photon map reported: {p}")
    if photons_one != photons_two:
        fail(f"photon maps differ: {photons_one} vs {photons_two}")
    print("ok:", photons_one[0])


main()
