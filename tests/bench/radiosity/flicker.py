#!/usr/bin/env python3
"""Radiosity flicker, frameray against povray.

    tests/bench/radiosity/flicker.py [--frameray PATH] [--povray PATH]
                                     [--width 160] [--height 120] [--out FILE]

flicker.pov is a static room seen by an orthographic camera that moves right
by exactly one pixel per frame, so frame n+1 is frame n moved one pixel left.
Without radiosity the two agree exactly (measured: 0.000 for both programs);
with radiosity the cache is rebuilt from the new camera in every frame and
what changes is flicker. Reported per program: the mean absolute difference
(0..255, per channel) between frame n and frame n+1 moved back, over every
consecutive pair, and the share of pixels differing by more than 4/255.
frameray runs twice: as povray does (each frame its own cache) and with
Radiosity_Stable=on (frames after the first start from its cache). Every
run uses one thread (+WT1). Standard library only.
"""

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
import png_compare  # noqa: E402

REPO_ROOT = HERE.parents[2]


def flicker(frames):
    total = 0.0
    count = 0
    changed = 0
    for a_path, b_path in zip(frames, frames[1:]):
        a = png_compare.read_png(a_path)
        b = png_compare.read_png(b_path)
        w, h, c = a.width, a.height, a.channels
        for y in range(h):
            for x in range(w - 1):
                ia = (y * w + x + 1) * c
                ib = (y * w + x) * c
                diffs = [abs(a.samples[ia + k] - b.samples[ib + k]) for k in range(3)]
                total += sum(diffs) / 3
                count += 1
                changed += max(diffs) > 4
    return total / count, changed / count


def render(program, binary, scene_dir, args, extra):
    work = Path(tempfile.mkdtemp(prefix=f"flicker-{program}-"))
    for name in ("flicker.pov", "flicker.ini"):
        shutil.copy(scene_dir / name, work / name)
    env = dict(os.environ)
    if program == "frameray":
        env["POVINI"] = "/dev/null"
    else:
        env["HOME"] = str(work)  # no personal povray.ini
    command = [binary, "-D", f"+W{args.width}", f"+H{args.height}", "flicker.ini", "+WT1",
               "+Oframe"] + extra
    subprocess.run(command, cwd=work, env=env, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, check=True)
    frames = sorted(work.glob("frame*.png"))
    result = flicker(frames)
    shutil.rmtree(work)
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--frameray", default=str(REPO_ROOT / "build/bin/frameray"))
    parser.add_argument("--povray", default=shutil.which("povray") or "povray")
    parser.add_argument("--width", type=int, default=160)
    parser.add_argument("--height", type=int, default=120)
    parser.add_argument("--frameray-option", action="append", default=[],
                        help="an extra switch or INI setting for frameray (repeatable)")
    args = parser.parse_args()
    rows = [("povray", render("povray", args.povray, HERE, args, []))]
    rows.append(("frameray", render("frameray", args.frameray, HERE, args, args.frameray_option)))
    rows.append(("frameray Radiosity_Stable=on",
                 render("frameray", args.frameray, HERE, args,
                        args.frameray_option + ["Radiosity_Stable=on"])))
    for name, (mean, share) in rows:
        print(f"{name}: mean abs difference {mean:.3f}/255, pixels changed {share * 100:.2f} %")


if __name__ == "__main__":
    main()
