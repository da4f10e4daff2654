#!/usr/bin/env python3
"""An INI carrying every povray 3.7 key frameray once refused renders as
povray renders it (issue 30).

tests/options/all_keys/all_keys.ini sets them all (Dither=on with
Dither_Method=FS among them), 48x36, no anti-aliasing. Checked against
povray 3.7.0.10's images of the same INI (made as all_keys.ini says):
- no `unknown option`, exit 0;
- with Dither=off the pixels equal povray's exactly (the keys that have no
  effect in povray have none in frameray);
- with Dither=on every sample is within one level of povray's and at most
  2 % differ: Floyd-Steinberg carries sub-level differences of the render
  itself into neighbouring pixels (frameray's dithering is exact on flat
  colours: unit test Dither.FloydSteinbergIsPovraysVariant), measured 69 of
  5184 samples;
- the dithered image differs from the undithered one (Dither has effect).

    all_keys_test.py FRAMERAY SCRATCH
"""
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from output_test import png_samples, read, report  # noqa: E402

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "all_keys")


def main():
    frameray, scratch = sys.argv[1], sys.argv[2]
    shutil.rmtree(scratch, ignore_errors=True)
    shutil.copytree(HERE, scratch)
    os.makedirs(os.path.join(scratch, "home"))
    env = {k: v for k, v in os.environ.items() if k not in ("POVINI", "POVRAYOPT", "XDG_CONFIG_HOME")}
    env["HOME"] = os.path.join(scratch, "home")
    failures = []
    images = {}
    for name, extra in (("dither", []), ("nodither", ["Dither=off"])):
        p = subprocess.run([frameray, "all_keys.ini", f"+O{name}.png"] + extra, cwd=scratch,
                           env=env, capture_output=True, text=True)
        if p.returncode != 0 or "unknown" in p.stderr:
            failures.append(f"{name}: exit {p.returncode}: {p.stderr}")
            continue
        images[name] = png_samples(read(os.path.join(scratch, f"{name}.png")))[3]
    golden = png_samples(read(os.path.join(HERE, "povray.png")))[3]
    golden_plain = png_samples(read(os.path.join(HERE, "povray_nodither.png")))[3]
    if "nodither" in images and images["nodither"] != golden_plain:
        n = sum(a != b for a, b in zip(images["nodither"], golden_plain))
        failures.append(f"Dither=off: {n} samples differ from povray's")
    if "dither" in images:
        diffs = [abs(a - b) for a, b in zip(images["dither"], golden)]
        differing = sum(d > 0 for d in diffs)
        print(f"Dither=FS: {differing} of {len(diffs)} samples differ from povray's, "
              f"at most by {max(diffs)}")
        if len(images["dither"]) != len(golden) or max(diffs) > 1 or differing > 0.02 * len(diffs):
            failures.append(f"Dither=FS: {differing} samples differ, at most by {max(diffs)}")
        if images["dither"] == images.get("nodither"):
            failures.append("Dither=on wrote the same pixels as Dither=off")
    return report("all_keys_test", failures)


if __name__ == "__main__":
    sys.exit(main())
