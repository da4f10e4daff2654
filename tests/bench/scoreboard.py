#!/usr/bin/env python3
"""The real-corpus scoreboard: POV-Ray's own example scenes, frameray vs povray.

    tests/bench/scoreboard.py [--frameray PATH] [--povray PATH] [--compare PATH]
                              [--width 160] [--height 120] [--only SUBSTRING]
                              [--timeout SECONDS] [--out-dir DIR] [--no-write]

Renders every example animation (EXAMPLES/animations/*/*.ini, each from its
own INI, so its Antialias, clock and frame range apply to both programs) and
a fixed list of still scenes (STILLS below) with frameray and with povray 3.7,
at the same size and with the same switches. Each program runs in its own
temporary copy of the scene's folder (scenes may write files); frameray gets
POVINI=/dev/null so that only the arguments and the scene's INI count, povray
reads its system povray.ini (library paths only, given -D) as it always does.

Per scene the table gives the frames each program wrote, the mean match of
frameray's frames against povray's (the conformance metric: the fraction of
pixels whose every channel is within 4/255, computed by png_compare.py
exactly as frameray-compare does, which is the fallback for other formats;
a frame povray wrote and frameray did not counts as 0), the wall time of
each whole run, the ratio frameray/povray and, when frameray stopped, its
first error line. The markdown goes to DIR/scoreboard-YYYY-MM-DD.md and
DIR/scoreboard-latest.md. Standard library only.
"""

import argparse
import datetime
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import zlib
from dataclasses import dataclass, field
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench import machine_description, program_version  # noqa: E402
import png_compare  # noqa: E402

REPO_ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = Path("/usr/share/doc/povray/examples")

# Still scenes, relative to EXAMPLES: varied features, each rendering in about
# a second at 160x120. The second group is scenes frameray could not render
# when the list was made (crand, polygon, #default, radiosity, fog turbulence,
# uv_mapping); they stay so the table shows when they start to work.
STILLS = [
    "camera/fisheye.pov",
    "camera/focalblur.pov",
    "camera/orthographic.pov",
    "camera/spherical.pov",
    "interior/fog_std.pov",
    "interior/atten1.pov",
    "interior/rainbow1.pov",
    "lights/circular.pov",
    "lights/parallel_lights.pov",
    "objects/blob.pov",
    "objects/lathe1a.pov",
    "objects/ttf1.pov",
    "advanced/sombrero.pov",
    "advanced/float5.pov",
    "advanced/swirlbox.pov",
    "language/trace.pov",
    # not rendered by frameray when chosen
    "lights/arealit1.pov",
    "objects/isosurfaces.pov",
    "objects/primitiv.pov",
    "objects/polygon.pov",
    "objects/mesh2.pov",
    "advanced/woodbox.pov",
    "interior/foglayr.pov",
    "radiosity/cornell.pov",
    # participating media (issue 25)
    "interior/media/media1.pov",
    "interior/media/media2.pov",
    "interior/media/media3.pov",
    "interior/media/media4.pov",
    "interior/media/media5.pov",
    "interior/media/hollow1.pov",
    "interior/media/hollow2.pov",
    "interior/media/hollow3.pov",
    "interior/media/galaxy.pov",
    "interior/media/micro.pov",
    "advanced/mediasky.pov",
]

IMAGE_SUFFIXES = (".png", ".tga", ".ppm", ".bmp", ".exr", ".hdr", ".jpg")
MATCH_RE = re.compile(r"match ([0-9.]+)")


@dataclass
class Run:
    wall: float = 0.0
    cpu: float = 0.0
    exit_code: int = 0
    frames: dict = field(default_factory=dict)  # file name -> Path
    log: str = ""


@dataclass
class Row:
    kind: str  # "animation" or "still"
    name: str
    povray: Run
    frameray: Run
    mean_match: float | None
    first_error: str


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--frameray", default=str(REPO_ROOT / "build/bin/frameray"))
    parser.add_argument("--povray", default=shutil.which("povray") or "povray")
    parser.add_argument("--compare", default=str(REPO_ROOT / "build/bin/frameray-compare"))
    parser.add_argument("--examples", default=str(EXAMPLES))
    parser.add_argument("--width", type=int, default=160)
    parser.add_argument("--height", type=int, default=120)
    parser.add_argument("--only", action="append", default=[],
                        help="run only scenes whose name contains this (repeatable)")
    parser.add_argument("--timeout", type=float, default=900.0,
                        help="seconds per run before it is killed")
    parser.add_argument("--out-dir", default=str(REPO_ROOT / "tests/bench/results"))
    parser.add_argument("--no-write", action="store_true",
                        help="print the table only, write no file")
    return parser.parse_args(argv)


def image_files(folder, before):
    """Images in folder that were not there before the run."""
    return {p.name: p for p in folder.iterdir()
            if p.is_file() and p.suffix.lower() in IMAGE_SUFFIXES and p.name not in before}


def run_renderer(command, cwd, env, timeout):
    """Runs one renderer in cwd; measures wall and CPU time of that child."""
    before = {p.name for p in cwd.iterdir()}
    log_path = cwd / "scoreboard-run.txt"
    run = Run()
    with open(log_path, "wb") as log:
        start = time.perf_counter()
        child = subprocess.Popen(command, cwd=cwd, env=env, stdin=subprocess.DEVNULL,
                                 stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
        deadline = start + timeout
        status = None
        usage = None
        while status is None:
            pid, raw, ru = os.wait4(child.pid, os.WNOHANG)
            if pid:
                status, usage = raw, ru
                break
            if time.perf_counter() > deadline:
                os.killpg(child.pid, 9)
                _, status, usage = os.wait4(child.pid, 0)
                log.write(b"\nerror: killed by the scoreboard after the timeout\n")
                break
            time.sleep(0.02)
        run.wall = time.perf_counter() - start
    child.returncode = os.waitstatus_to_exitcode(status)
    run.exit_code = child.returncode
    run.cpu = usage.ru_utime + usage.ru_stime
    run.frames = image_files(cwd, before)
    run.log = log_path.read_text(errors="replace")
    return run


def first_error(log):
    """frameray's first `not supported yet: ...` or `error: ...`, without the
    file:line prefix (the file is usually an include, named in the log)."""
    for line in log.splitlines():
        for marker in ("not supported yet:", "error:"):
            at = line.find(marker)
            if at >= 0:
                text = line[at:]
                if text.startswith("error: not supported yet:"):
                    text = text[len("error: "):]
                return text.strip()[:140]
    return ""


def frame_match(compare, test, golden):
    try:
        return png_compare.compare_files(test, golden).match
    except (png_compare.UnsupportedImage, OSError, ValueError, IndexError, zlib.error):
        pass  # e.g. a TGA frame or a size mismatch: let frameray-compare judge
    done = subprocess.run([compare, str(test), str(golden), "--min-match", "0"],
                          capture_output=True, text=True)
    found = MATCH_RE.search(done.stdout)
    return float(found.group(1)) if found else 0.0


def score(kind, name, folder, target, args, scratch):
    """Renders one scene (INI or .pov in folder) with both programs."""
    switches = ["-D", f"+W{args.width}", f"+H{args.height}", target]
    runs = {}
    for program in ("povray", "frameray"):
        copy = scratch / program
        shutil.rmtree(copy, ignore_errors=True)
        shutil.copytree(folder, copy)
        env = dict(os.environ)
        binary = args.povray
        if program == "frameray":
            env["POVINI"] = "/dev/null"
            binary = args.frameray
        runs[program] = run_renderer([binary] + switches, copy, env, args.timeout)
    pov, fr = runs["povray"], runs["frameray"]
    matches = []
    for frame_name in sorted(pov.frames):
        if frame_name in fr.frames:
            matches.append(frame_match(args.compare, fr.frames[frame_name], pov.frames[frame_name]))
        else:
            matches.append(0.0)
    mean = sum(matches) / len(matches) if matches else None
    error = first_error(fr.log) if fr.exit_code != 0 else ""
    if fr.exit_code != 0 and not error:
        error = f"exit {fr.exit_code}"
    return Row(kind, name, pov, fr, mean, error)


def entries(args):
    examples = Path(args.examples)
    found = []
    for ini in sorted(examples.glob("animations/*/*.ini")):
        found.append(("animation", f"animations/{ini.parent.name}/{ini.name}", ini.parent, ini.name))
    for still in STILLS:
        path = examples / still
        found.append(("still", still, path.parent, path.name))
    if args.only:
        found = [e for e in found if any(o in e[1] for o in args.only)]
    return found


def fully_rendered(row):
    return (row.frameray.exit_code == 0 and row.povray.frames
            and set(row.povray.frames) <= set(row.frameray.frames))


def markdown(rows, args, started, load_at_start):
    lines = [
        "# Real-corpus scoreboard: POV-Ray 3.7 examples, frameray vs povray",
        "",
        f"- date: {started.isoformat(timespec='seconds')}",
        f"- machine: {machine_description()}; load average at start: {load_at_start}",
        f"- frameray: `{args.frameray}` (POVINI=/dev/null); povray: `{args.povray}` "
        f"({program_version([args.povray, '--version'])})",
        f"- size: {args.width}x{args.height}, both with `-D +W{args.width} +H{args.height}` "
        "plus the scene's own INI (animations) or nothing else (stills: no anti-aliasing)",
        "- match: mean over povray's frames of the fraction of pixels within 4/255 on every "
        "channel (frameray-compare's metric, tests/bench/png_compare.py); a frame frameray "
        "did not write counts 0",
        "- times: wall and CPU (user + sys) seconds of the whole run (start-up, parse, "
        "render, write, all frames; both use every core); the machine may be shared, so "
        "treat ratios as rough",
        "",
        "| kind | scene | povray frames | frameray frames | mean match | povray s | frameray s "
        "| ratio | povray CPU s | frameray CPU s | frameray stopped with |",
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|",
    ]
    for r in rows:
        match = f"{r.mean_match:.4f}" if r.mean_match is not None else "—"
        ratio = f"{r.frameray.wall / r.povray.wall:.2f}" if r.povray.wall > 0 else "n/a"
        pov_frames = str(len(r.povray.frames))
        if r.povray.exit_code != 0:
            pov_frames += f" (exit {r.povray.exit_code})"
        error = r.first_error.replace("|", "\\|")
        if r.povray.exit_code != 0 and not r.povray.frames and error:
            error += " (povray fails too)"
        lines.append(f"| {r.kind} | {r.name} | {pov_frames} | {len(r.frameray.frames)} | "
                     f"{match} | {r.povray.wall:.2f} | {r.frameray.wall:.2f} | {ratio} | "
                     f"{r.povray.cpu:.2f} | {r.frameray.cpu:.2f} | {error} |")
    scored = [r.mean_match for r in rows if r.mean_match is not None]
    full = [r for r in rows if fully_rendered(r)]
    full_matches = [r.mean_match for r in full if r.mean_match is not None]
    pov_total = sum(r.povray.wall for r in rows)
    fr_total = sum(r.frameray.wall for r in rows)
    pov_full = sum(r.povray.wall for r in full)
    fr_full = sum(r.frameray.wall for r in full)
    pov_cpu = sum(r.povray.cpu for r in full)
    fr_cpu = sum(r.frameray.cpu for r in full)

    def ratio_text(a, b):
        return f"{a / b:.2f}" if b > 0 else "n/a"

    lines += [
        "",
        "## Totals",
        "",
        f"- scenes: {len(rows)} ({sum(r.kind == 'animation' for r in rows)} animations, "
        f"{sum(r.kind == 'still' for r in rows)} stills)",
        f"- fully rendered by frameray (exit 0, every frame povray wrote): {len(full)} "
        f"of {len(rows)} ({sum(1 for r in rows if r.povray.frames)} that povray renders)",
        f"- mean match over all scenes (a scene frameray stopped on counts its missing "
        f"frames as 0): {sum(scored) / len(scored):.4f}" if scored else "- mean match: —",
        f"- mean match over the fully rendered scenes: "
        f"{sum(full_matches) / len(full_matches):.4f}" if full_matches else
        "- mean match over the fully rendered scenes: —",
        f"- frames: povray {sum(len(r.povray.frames) for r in rows)}, frameray "
        f"{sum(len(r.frameray.frames) for r in rows)}",
        f"- wall time, all scenes: povray {pov_total:.1f} s, frameray {fr_total:.1f} s "
        f"(ratio {ratio_text(fr_total, pov_total)}; frameray's time includes runs that "
        "stopped early)",
        f"- wall time, fully rendered scenes only: povray {pov_full:.1f} s, frameray "
        f"{fr_full:.1f} s (ratio {ratio_text(fr_full, pov_full)}); CPU time: povray "
        f"{pov_cpu:.1f} s, frameray {fr_cpu:.1f} s (ratio {ratio_text(fr_cpu, pov_cpu)})",
        "",
        "Regenerate: `tests/bench/scoreboard.py` (build Release first).",
        "",
    ]
    return "\n".join(lines)


def main(argv):
    args = parse_args(argv)
    for tool in (args.frameray, args.compare):
        if not Path(tool).exists():
            sys.exit(f"scoreboard: {tool} not found (build first: bash scripts/build.sh)")
    args.frameray = str(Path(args.frameray).resolve())
    args.compare = str(Path(args.compare).resolve())
    started = datetime.datetime.now().astimezone()
    load_at_start = " ".join(Path("/proc/loadavg").read_text().split()[:3])
    rows = []
    with tempfile.TemporaryDirectory(prefix="frameray-scoreboard.") as scratch:
        for kind, name, folder, target in entries(args):
            row = score(kind, name, folder, target, args, Path(scratch))
            match = f"{row.mean_match:.4f}" if row.mean_match is not None else "—"
            print(f"{name}: povray {len(row.povray.frames)} frames {row.povray.wall:.1f}s, "
                  f"frameray {len(row.frameray.frames)} frames {row.frameray.wall:.1f}s, "
                  f"match {match} {row.first_error}", file=sys.stderr, flush=True)
            rows.append(row)
    text = markdown(rows, args, started, load_at_start)
    print(text)
    if not args.no_write:
        out = Path(args.out_dir)
        out.mkdir(parents=True, exist_ok=True)
        dated = out / f"scoreboard-{started.date().isoformat()}.md"
        dated.write_text(text)
        shutil.copyfile(dated, out / "scoreboard-latest.md")
        print(f"scoreboard: wrote {dated} and scoreboard-latest.md", file=sys.stderr)


if __name__ == "__main__":
    main(sys.argv[1:])
