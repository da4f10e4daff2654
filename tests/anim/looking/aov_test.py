#!/usr/bin/env python3
"""Output_AOVs: extra layers in EXR frames (issue 29).

    aov_test.py FRAMERAY SCENE WORKDIR

1. +FE with Output_AOVs=depth,normal,object_id,albedo: `oiiotool --info -v`
   lists every layer's channels (Z; N.x N.y N.z; objectId; albedo.R G B)
   beside R G B, the colour as half floats, the layers as floats, and the
   compression asked (Exr_Compression=piz).
2. The values at known pixels: the plane below the camera (object 1,
   normal +y, depth > 0, albedo of its checker), the box in the middle
   (object 2, normal -z), the background (object 0, depth 1e10).
3. Without Output_AOVs the EXR holds R G B only; Output_AOVs without +FE
   and Output_AOVs=motion stop before anything is rendered.
"""
import os
import re
import shutil
import subprocess
import sys


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run(args, expect=0):
    r = subprocess.run(args, capture_output=True, text=True)
    if r.returncode != expect:
        fail("%s exited %d (expected %d): %s" % (" ".join(args), r.returncode, expect, r.stderr))
    return r


def channels(path):
    info = run(["oiiotool", "--info", "-v", path]).stdout
    m = re.search(r"channel list: (.*)", info)
    if not m:
        fail("oiiotool lists no channels for %s:\n%s" % (path, info))
    found = [c.strip() for c in m.group(1).split(",")]
    # "R (half)" when the channels' types differ, "R" when all are alike.
    return {c.split(" (")[0]: (c.split("(")[1].rstrip(")") if "(" in c else "") for c in found}, info


def pixel(path, x, y):
    dump = run(["oiiotool", "--dumpdata", path]).stdout
    m = re.search(r"Pixel \(%d, %d\): (.*)" % (x, y), dump)
    if not m:
        fail("no pixel (%d, %d) in %s" % (x, y, path))
    return [float(v) for v in m.group(1).split()]


def main():
    frameray, scene, work = sys.argv[1:4]
    if not shutil.which("oiiotool"):
        fail("oiiotool is missing (Debian package openimageio-tools; scripts/setup.sh installs it)")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    base = [frameray, scene, "+W64", "+H48", "+KFI1", "+KFF2", "-V", "+FE"]
    out = os.path.join(work, "aov") + "/"
    run(base + ["+O" + out, "Output_AOVs=depth,normal,object_id,albedo", "Exr_Compression=piz"])
    path = os.path.join(out, "spin1.exr")
    chans, info = channels(path)
    expected = {"R": "half", "G": "half", "B": "half", "Z": "float", "N.x": "float",
                "N.y": "float", "N.z": "float", "objectId": "float", "albedo.R": "float",
                "albedo.G": "float", "albedo.B": "float"}
    if chans != expected:
        fail("channels %s, expected %s" % (chans, expected))
    if 'compression: "piz"' not in info:
        fail("compression piz not in:\n" + info)
    names = ["R", "G", "B", "Z", "objectId", "N.x", "N.y", "N.z", "albedo.R", "albedo.G",
             "albedo.B"]
    order = re.search(r"channel list: (.*)", info).group(1)
    order = [c.split(" (")[0].strip() for c in order.split(",")]

    def layers(x, y):
        return dict(zip(order, pixel(path, x, y)))

    plane, box, sky = layers(32, 45), layers(32, 28), layers(2, 2)
    checks = [
        (plane["objectId"], 1), (plane["N.y"], 1), (plane["N.x"], 0),
        (box["objectId"], 2), (box["N.z"], -1), (box["albedo.R"], 0.1),
        (box["albedo.G"], 0.2), (box["albedo.B"], 0.9),
        (sky["objectId"], 0), (sky["Z"], 1e10), (sky["N.y"], 0),
    ]
    for got, want in checks:
        if abs(got - want) > 1e-3 * max(1, abs(want)):
            fail("pixel values %s / %s / %s: got %s, expected %s" % (plane, box, sky, got, want))
    # The camera is 6.3 units from the box's front face centre, 2 above
    # the plane: depths along the rays.
    if not (5.0 < box["Z"] < 7.0) or not (2.0 < plane["Z"] < 4.0):
        fail("depths box %s plane %s" % (box["Z"], plane["Z"]))
    if set(names) != set(order):
        fail("channel order %s" % order)

    # Without the option: the colour alone.
    plain = os.path.join(work, "plain") + "/"
    run(base + ["+O" + plain])
    chans, _ = channels(os.path.join(plain, "spin1.exr"))
    if set(chans) != {"R", "G", "B"}:
        fail("an EXR without Output_AOVs has channels %s" % chans)

    # Errors before rendering.
    r = run(base[:-1] + ["+FN", "+O" + os.path.join(work, "png") + "/", "Output_AOVs=depth"], 2)
    if "Output_AOVs needs EXR frames" not in r.stderr:
        fail("AOVs without +FE: " + r.stderr)
    r = run(base + ["+O" + os.path.join(work, "motion") + "/", "Output_AOVs=depth,motion"], 2)
    if "not supported yet: Output_AOVs (Output_AOVs=motion" not in r.stderr:
        fail("motion: " + r.stderr)
    r = run(base + ["+O" + os.path.join(work, "bad") + "/", "Output_AOVs=depht"], 2)
    if "unknown layer 'depht'" not in r.stderr:
        fail("a misspelt layer: " + r.stderr)
    if os.path.exists(os.path.join(work, "png")) and os.listdir(os.path.join(work, "png")):
        fail("frames were written despite the error")
    print("aov_test: OK")


main()
