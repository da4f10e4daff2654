#!/usr/bin/env python3
"""povray against itself on the radiosity corpus: the noise floor of the match.

    tests/bench/radiosity/noise_floor.py [--povray PATH] [--width 160] [--height 120]

povray 3.7's radiosity samples depend on which thread reaches a spot first,
so two runs of the same scene need not agree. Per scene (the stills at
WIDTHxHEIGHT with -A, raddem from its INI like the scoreboard) this renders
povray three times: +WT1 twice and +WT2 once, and prints the match (pixels
within 4/255 on every channel, png_compare.py) of +WT1 against +WT1 and of
+WT1 against +WT2. Where that is below 0.97 no renderer can be expected to
match povray better than povray matches itself. Standard library (numpy if
there).
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

EXAMPLES = Path("/usr/share/doc/povray/examples")
SCENES = ["radiosity/cornell.pov", "radiosity/patio-radio_36.pov",
          "radiosity/patio-radio_37.pov", "radiosity/rad_def_test_36.pov",
          "radiosity/rad_def_test_37.pov", "radiosity/radiosity2.pov",
          "radiosity/radiosity3.pov", "radiosity/radiosity_36.pov",
          "radiosity/radiosity_37.pov", "advanced/object_pattern.pov",
          "animations/raddem/raddem.ini"]


def render(povray, scene, threads, args):
    """Renders scene in a copy of its folder; returns the frames' paths in
    order and the folder (the caller removes it)."""
    source = EXAMPLES / scene
    work = Path(tempfile.mkdtemp(prefix="noise-floor-"))
    folder = work / "scene"
    shutil.copytree(source.parent, folder)
    env = dict(os.environ, HOME=str(work))
    size = [f"+W{args.width}", f"+H{args.height}"]
    if scene.endswith(".ini"):
        command = [povray, "-D"] + size + [f"+WT{threads}", source.name, "+Oout"]
    else:
        command = [povray, "-D", "-A"] + size + [f"+WT{threads}", f"+I{source.name}",
                                                 "+Oout.png"]
    subprocess.run(["nice"] + command, cwd=folder, env=env, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, check=True)
    return sorted(folder.glob("out*.png")), work


def mean_match(a_frames, b_frames):
    values = [png_compare.compare_files(a, b).match for a, b in zip(a_frames, b_frames)]
    return sum(values) / len(values) if values else 0.0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--povray", default=shutil.which("povray") or "povray")
    parser.add_argument("--width", type=int, default=160)
    parser.add_argument("--height", type=int, default=120)
    parser.add_argument("--only", action="append", default=[])
    args = parser.parse_args()
    print("| scene | +WT1 vs +WT1 | +WT1 vs +WT2 |")
    print("|---|---|---|")
    for scene in SCENES:
        if args.only and not any(o in scene for o in args.only):
            continue
        one, w1 = render(args.povray, scene, 1, args)
        again, w2 = render(args.povray, scene, 1, args)
        two, w3 = render(args.povray, scene, 2, args)
        print(f"| {scene} | {mean_match(one, again):.4f} | {mean_match(one, two):.4f} |",
              flush=True)
        for w in (w1, w2, w3):
            shutil.rmtree(w)


if __name__ == "__main__":
    main()
