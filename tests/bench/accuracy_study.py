#!/usr/bin/env python3
"""What accuracy costs in time: sweeps frameray's accuracy knobs on a scene.

    tests/bench/accuracy_study.py SCENE.pov [--knobs K1,K2,...] [--out DIR]
                                  [--frames N] [--reps N] [--threads N] [--no-povray]
                                  [--width W --height H]
    tests/bench/accuracy_study.py --run-all [--out DIR]   # every scene in
                                  # tests/bench/accuracy/, into
                                  # tests/bench/results/accuracy/ by default

A study scene says in its header comments which knobs it stresses, its
baseline switches and the switches of its converged reference:

    // study-knobs: max_trace adc_bailout quality
    // study-baseline: +A0.3 +R3 -J Declare=MaxTrace=5
    // study-reference: +A0.0 +R4 -J Declare=MaxTrace=40

Scene-side knobs (max_trace_level, adc_bailout, area-light grid and
adaptive level, isosurface accuracy, sturm) are `#declare`d by the scene
behind `#ifndef` and set with Declare=NAME=VALUE, which both programs take.

Each knob is swept one at a time from the baseline (the other switches stay
at the baseline). For every setting: frameray's render time (CPU seconds per
frame of a run that renders the same frame --frames times, less frameray's
start-up CPU; the best of --reps runs), povray 3.7's time at the same
switches (the CPU-seconds it reports for parse + bounding + trace), and
the error of frameray's image against the reference rendered by frameray:
RMSE (0..255 scale), PSNR over R, G, B, and the fraction of pixels within
4/255 on every channel (the conformance metric, tests/bench/png_compare.py).
Also recorded: the "isolated" PSNR against the sweep's own most accurate
setting (the knob's effect alone, without the baseline's other errors) and
povray's PSNR against the same reference (how far the two programs agree).

Then, per error budget (draft / preview / final), a preset combining every
knob at its cheapest setting whose isolated error clears the budget is
rendered and measured. Writes DIR/SCENE.csv, DIR/SCENE.png (PSNR against
time, one curve per knob, the presets and the Pareto front marked) and
DIR/SCENE.md (presets, tables, findings); --run-all also
writes DIR/README.md, a summary across scenes. Needs numpy and matplotlib
for the plot (Debian python3-numpy, python3-matplotlib; scripts/setup.sh).
"""

import os
import sys

# The Debian matplotlib lives in /usr/bin/python3's site-packages; a python3
# from pyenv or a venv first on PATH may not see it.
import importlib.util  # noqa: E402

if importlib.util.find_spec("matplotlib") is None:
    if os.path.exists("/usr/bin/python3") and os.path.realpath(sys.executable) != \
            os.path.realpath("/usr/bin/python3") and not os.environ.get("ACCURACY_STUDY_REEXEC"):
        os.environ["ACCURACY_STUDY_REEXEC"] = "1"
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)

import argparse  # noqa: E402
import csv  # noqa: E402
import datetime  # noqa: E402
import math  # noqa: E402
import re  # noqa: E402
import shutil  # noqa: E402
import resource  # noqa: E402
import subprocess  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from dataclasses import dataclass, field  # noqa: E402
from pathlib import Path  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench import machine_description, program_version  # noqa: E402
import png_compare  # noqa: E402

REPO_ROOT = Path(__file__).resolve().parents[2]
SCENES_DIR = REPO_ROOT / "tests/bench/accuracy"
DEFAULT_OUT = REPO_ROOT / "tests/bench/results/accuracy"

# Error budgets of the recommendation table: PSNR (dB) against the converged
# reference. 30 dB: structure right, visible noise/banding/aliasing; 38 dB:
# differences hard to see side by side; 45 dB: under about 1.5/255 RMS.
BUDGETS = [("draft", 30.0), ("preview", 38.0), ("final", 45.0)]
PSNR_CAP = 99.0  # stands for "identical" (infinite PSNR) in plots and sums


@dataclass
class Knob:
    title: str
    values: list  # (label, [switches]) from cheapest / least accurate to most accurate
    needs_aa: bool = False


def _declares(name, values):
    return [(str(v), [f"Declare={name}={v}"]) for v in values]


KNOBS = {
    # povray refuses the switch +A1.0 ("Failed to parse command-line
    # option"), so that one threshold is given as an INI option.
    "aa_threshold": Knob("Antialias_Threshold (+A)", [
        ("off", ["-A"]), ("1.0", ["+A", "Antialias_Threshold=1.0"])] + [
        (t, [f"+A{t}"]) for t in ("0.5", "0.3", "0.1", "0.05", "0.0")]),
    "aa_depth": Knob("Antialias_Depth (+R)", [(str(d), [f"+R{d}"]) for d in range(1, 6)],
                     needs_aa=True),
    "jitter": Knob("Jitter (+J)", [("off", ["-J"]), ("on", ["+J"])], needs_aa=True),
    "sampling_method": Knob("Sampling_Method (+AM)", [("1", ["+AM1"]), ("2", ["+AM2"])],
                            needs_aa=True),
    "max_trace": Knob("max_trace_level", _declares("MaxTrace", (1, 2, 3, 5, 10, 20))),
    "adc_bailout": Knob("adc_bailout", _declares(
        "AdcBailout", ("0.3", "0.1", "0.03", "0.01", "0.0039", "0.001", "0.0001"))),
    "area_size": Knob("area_light grid (N x N)", _declares("AreaSize", (1, 2, 3, 5, 9, 17))),
    "area_adaptive": Knob("area_light adaptive (17 x 17 grid)", [
        (str(a), ["Declare=AreaSize=17", f"Declare=AreaAdaptive={a}"]) for a in range(0, 5)]),
    "iso_accuracy": Knob("isosurface accuracy", _declares(
        "IsoAccuracy", ("0.1", "0.03", "0.01", "0.001", "0.0001", "0.00001"))),
    "sturm": Knob("sturm", [("off", ["Declare=Sturm=0"]), ("on", ["Declare=Sturm=1"])]),
    "quality": Knob("Quality (+Q)", [(str(q), [f"+Q{q}"]) for q in range(0, 12)]),
    # Radiosity (issue 26): the scene declares each setting behind #ifndef.
    "rad_count": Knob("radiosity count", _declares("RadCount", (10, 20, 35, 70, 150, 300))),
    "rad_error_bound": Knob("radiosity error_bound", _declares(
        "RadErrorBound", ("3", "1.8", "1", "0.5", "0.25"))),
    "rad_pretrace_end": Knob("radiosity pretrace_end", _declares(
        "RadPretraceEnd", ("0.08", "0.04", "0.02", "0.01", "0.005"))),
    "rad_recursion": Knob("radiosity recursion_limit", _declares("RadRecursion", (1, 2, 3))),
    "rad_nearest": Knob("radiosity nearest_count", _declares("RadNearest", (1, 3, 5, 10, 20))),
    # Participating media (issue 25), method 3 (frameray stops on methods 1
    # and 2, so `method` has no sweep yet): declared by the scene.
    "media_intervals": Knob("media intervals", _declares("MediaIntervals", (1, 2, 3, 5, 10))),
    "media_samples": Knob("media samples", _declares("MediaSamples", (1, 3, 5, 10, 20, 40))),
    "media_aa_level": Knob("media aa_level", _declares("MediaAaLevel", (1, 2, 3, 4, 5))),
    "media_aa_threshold": Knob("media aa_threshold", _declares(
        "MediaAaThreshold", ("0.5", "0.2", "0.1", "0.05", "0.01"))),
    # Photon mapping (issue 27): the global photons block's spacing, gather
    # max and jitter, declared by the scene.
    "photons_spacing": Knob("photons spacing", _declares(
        "PhotonSpacing", ("0.2", "0.1", "0.05", "0.03", "0.02", "0.01", "0.005"))),
    "photons_gather": Knob("photons gather max", _declares(
        "PhotonGatherMax", (25, 50, 100, 200, 400))),
    "photons_jitter": Knob("photons jitter", _declares("PhotonJitter", ("0", "0.4", "1"))),
}


@dataclass
class Render:
    # Render CPU seconds: frameray's process CPU minus its start-up CPU;
    # povray's own CPU-seconds for parse + bounding + trace.
    time: float | None = None
    wall: float | None = None  # seconds of the whole process
    image: Path | None = None
    error: str = ""
    cpu: float | None = None  # user + sys seconds of the whole process
    frame_wall: float | None = None  # wall seconds the renderer reports for the frame


@dataclass
class Point:
    knob: str
    label: str
    switches: list
    frameray: Render
    povray: Render | None
    rmse: float | None = None
    psnr: float | None = None
    within: float | None = None
    isolated_psnr: float | None = None
    povray_psnr: float | None = None
    povray_within: float | None = None


@dataclass
class Study:
    scene: Path
    description: list
    knobs: list
    baseline: list
    reference_switches: list
    reference: Render | None = None
    points: list = field(default_factory=list)
    presets: list = field(default_factory=list)  # (budget name, Point), combined settings


# ---------------------------------------------------------------- switches

def switch_key(switch):
    """Which option a switch sets, so that a later one replaces it."""
    if switch.startswith("Declare="):
        return switch.split("=", 2)[0] + "=" + switch.split("=", 2)[1]
    if "=" in switch:  # an INI option, Key=Value
        return switch.split("=", 1)[0].upper()
    body = switch.lstrip("+-")
    return re.match(r"[A-Za-z]*", body).group(0).upper() or switch


def merge(base, changes):
    merged = {switch_key(s): s for s in base}
    for s in changes:
        merged[switch_key(s)] = s
    return list(merged.values())


def read_header(scene):
    description, knobs, baseline, reference = [], [], [], []
    for line in scene.read_text().splitlines():
        if not line.startswith("//"):
            break
        text = line[2:].strip()
        if text.startswith("study-knobs:"):
            knobs = text.split(":", 1)[1].split()
        elif text.startswith("study-baseline:"):
            baseline = text.split(":", 1)[1].split()
        elif text.startswith("study-reference:"):
            reference = text.split(":", 1)[1].split()
        else:
            description.append(text)
    return description, knobs, baseline, reference


# ---------------------------------------------------------------- running

FRAME_TIME = re.compile(r"frame \d+: ([0-9.]+) s")
POVRAY_CPU = re.compile(r"(Parse|Bounding|Photon|Radiosity|Trace) Time:.*\(([0-9.]+) seconds\)"
                        r"\s*using \d+ thread\(s\) with ([0-9.]+) CPU-seconds")


def render(program, binary, scene, switches, out_dir, args, frames=None):
    """Renders the scene `frames` times in one process (an animation whose
    frames are all the same picture: the study scenes ignore the clock), so
    that the start-up and the scheduling noise of a shared machine spread
    over several frames; returns the per-frame times and the first image."""
    frames = frames or args.frames
    out_dir = Path(out_dir)
    shutil.rmtree(out_dir, ignore_errors=True)
    out_dir.mkdir(parents=True)
    command = [binary, scene.name, f"+W{args.width}", f"+H{args.height}", "-D",
               f"+WT{args.threads}", *switches, "+KFI1", f"+KFF{frames}", f"+O{out_dir}/"]
    env = dict(os.environ)
    if program == "frameray":
        env["POVINI"] = "/dev/null"
    # Children run one at a time, so the change of RUSAGE_CHILDREN is this
    # child's CPU time (all threads, start-up included): steadier than wall
    # time when other jobs share the cores.
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    with tempfile.TemporaryFile() as log:
        child = subprocess.Popen(command, cwd=scene.parent, env=env, stdin=subprocess.DEVNULL,
                                 stdout=log, stderr=subprocess.STDOUT)
        try:
            child.wait(timeout=args.timeout)
        except subprocess.TimeoutExpired:
            child.kill()
        wall = time.perf_counter() - start
        log.seek(0)
        output = log.read().decode(errors="replace")
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
    images = sorted(out_dir.glob("*.png"))
    if child.returncode != 0 or len(images) != frames:
        line = next((l for l in output.splitlines() if "error" in l.lower()), "")
        return Render(wall=wall, error=line.strip()[:160] or f"exit {child.returncode}")
    if program == "frameray":
        found = FRAME_TIME.findall(output)
        frame_wall = sum(float(w) for w in found) / frames if found else wall / frames
        seconds = max(0.0, cpu - args.startup_cpu) / frames
    else:
        found = POVRAY_CPU.findall(output)
        frame_wall = sum(float(w) for _, w, _ in found) / frames if found else wall / frames
        seconds = sum(float(c) for _, _, c in found) / frames if found else cpu / frames
    return Render(seconds, wall, images[0], cpu=cpu, frame_wall=frame_wall)


def startup_cpu(args, scratch):
    """CPU seconds frameray spends on an empty 1x1 frame (loading its
    libraries, parsing nothing): subtracted from every run so that the
    times compare the work the knobs change."""
    scene = Path(scratch) / "empty.pov"
    scene.write_text("#version 3.7;\ncamera { location -z look_at 0 }\n")
    saved = (args.width, args.height)
    args.width, args.height, args.startup_cpu = 1, 1, 0.0
    runs = [render("frameray", args.frameray, scene, [], Path(scratch) / "empty", args, 1)
            for _ in range(3)]
    args.width, args.height = saved
    return min(r.cpu for r in runs if r.cpu is not None)


def render_best(program, binary, scene, switches, out_dir, args, reps):
    best = None
    for _ in range(max(1, reps)):
        r = render(program, binary, scene, switches, out_dir, args)
        if r.error:
            return r
        if best is None or r.time < best.time:
            best = r
    return best


def psnr_value(p):
    return PSNR_CAP if p is None or math.isinf(p) else min(p, PSNR_CAP)


def run_study(scene, args, scratch):
    description, knobs, baseline, reference = read_header(scene)
    if args.knobs:
        knobs = args.knobs
    unknown = [k for k in knobs if k not in KNOBS]
    if unknown:
        sys.exit(f"accuracy_study: unknown knob(s) {unknown}; known: {', '.join(KNOBS)}")
    study = Study(scene, description, knobs, baseline, reference or baseline)
    work = Path(scratch) / scene.stem
    work.mkdir(parents=True, exist_ok=True)
    log = lambda text: print(f"{scene.stem}: {text}", file=sys.stderr, flush=True)  # noqa: E731

    study.reference = render("frameray", args.frameray, scene, study.reference_switches,
                             work / "reference", args, 1)
    if study.reference.error:
        sys.exit(f"accuracy_study: the reference render failed: {study.reference.error}")
    log(f"reference {' '.join(study.reference_switches)}: {study.reference.time:.2f} s")
    reference_image = png_compare.read_image(study.reference.image)

    cache = {}  # switches -> (frameray Render, povray Render)

    def measure(knob_name, label, switches):
        key = tuple(switches)
        if key not in cache:
            n = len(cache)
            fr = render_best("frameray", args.frameray, scene, switches,
                             work / f"f{n}", args, args.reps)
            pov = None if args.no_povray else render(
                "povray", args.povray, scene, switches, work / f"p{n}", args)
            cache[key] = (fr, pov)
            log(f"{knob_name}={label}: frameray {fmt(fr.time, '{:.2f}')} s, povray "
                f"{fmt(pov.time if pov else None, '{:.2f}')} s {fr.error} "
                f"{pov.error if pov else ''}")
        fr, pov = cache[key]
        point = Point(knob_name, label, switches, fr, pov)
        if fr.image:
            image = png_compare.read_image(fr.image)
            c = png_compare.compare(image, reference_image)
            point.rmse, point.psnr, point.within = c.rmse, c.psnr_db, c.match
            point._image = image
        if pov and pov.image:
            c = png_compare.compare(png_compare.read_image(pov.image), reference_image)
            point.povray_psnr, point.povray_within = c.psnr_db, c.match
        return point

    for knob_name in knobs:
        knob = KNOBS[knob_name]
        base = list(baseline)
        aa_on = any(switch_key(x) == "A" and x.startswith("+") for x in base)
        if knob.needs_aa and not aa_on:
            base = merge(base, ["+A0.3"])
        sweep = [measure(knob_name, label, merge(base, changes))
                 for label, changes in knob.values]
        # The knob's most accurate setting is the one closest to the reference
        # (for most knobs the last; not for jitter or the sampling method).
        scored = [p for p in sweep if p.psnr is not None]
        best = max(reversed(scored), key=lambda p: psnr_value(p.psnr)) if scored else sweep[-1]
        for point in sweep:
            if getattr(point, "_image", None) is not None and getattr(best, "_image", None) is not None:
                point.isolated_psnr = png_compare.compare(point._image, best._image).psnr_db
        for point in sweep:
            point._image = None
        study.points.extend(sweep)

    # Combined presets: every knob at its cheapest setting whose isolated
    # PSNR clears the budget by a margin (errors of several knobs add up),
    # rendered to check; the margin grows until the combination meets the
    # budget or every knob is at its most accurate setting.
    for name, budget in BUDGETS:
        for margin in (3.0, 10.0, 1000.0):
            switches, picks, changes_so_far = list(baseline), [], []
            for knob_name in knobs:
                sweep = [p for p in study.points if p.knob == knob_name]
                ok = [p for p in sweep if p.isolated_psnr is not None
                      and psnr_value(p.isolated_psnr) >= budget + margin]
                best = max((p for p in reversed(sweep) if p.psnr is not None),
                           key=lambda p: psnr_value(p.psnr), default=sweep[-1])
                pick = ok[0] if ok else best
                # A knob's changes may carry a setting an earlier knob already
                # picked (area_adaptive sweeps on a 17x17 grid): the earlier pick
                # stays.
                taken = {switch_key(x) for x in changes_so_far}
                changes = [x for x in dict(KNOBS[knob_name].values)[pick.label]
                           if switch_key(x) not in taken]
                changes_so_far += changes
                switches = merge(switches, changes)
                picks.append(f"{knob_name}={pick.label}")
            point = measure(f"preset:{name}", ", ".join(picks), switches)
            point._image = None
            if point.psnr is not None and psnr_value(point.psnr) >= budget:
                break
        study.presets.append((name, point))
    return study


# ---------------------------------------------------------------- analysis

def pareto(points):
    """Points not beaten by another on both time (lower) and PSNR (higher)."""
    ok = [p for p in points if p.frameray.time is not None and p.psnr is not None]
    front = []
    for p in sorted(ok, key=lambda p: (p.frameray.time, -psnr_value(p.psnr))):
        if not front or psnr_value(p.psnr) > psnr_value(front[-1].psnr):
            front.append(p)
    return front


def cheapest_within(points, budget):
    ok = [p for p in points if p.frameray.time is not None and p.psnr is not None
          and psnr_value(p.psnr) >= budget]
    if not ok:
        return None
    # Times within 10% of the fastest are a tie on a shared machine; among
    # those, the most accurate wins.
    fastest = min(p.frameray.time for p in ok)
    ties = [p for p in ok if p.frameray.time <= fastest * 1.1]
    return max(ties, key=lambda p: psnr_value(p.psnr))


def fmt(value, pattern="{:.3f}", missing="—"):
    if value is None:
        return missing
    if isinstance(value, float) and math.isinf(value):
        return "inf"
    return pattern.format(value)


def setting_text(point, study):
    """The switches that differ from the baseline, or 'baseline'."""
    changed = [s for s in point.switches if s not in study.baseline]
    return " ".join(changed) if changed else "baseline"


def knob_finding(study, knob_name):
    sweep = [p for p in study.points if p.knob == knob_name and p.psnr is not None]
    if not sweep:
        return "no setting rendered"
    first, last = sweep[0], sweep[-1]
    # Smallest setting whose isolated PSNR says it is within 0.5/255 RMS of
    # the sweep's most accurate setting (~54 dB).
    enough = next((p for p in sweep if psnr_value(p.isolated_psnr) >= 54.0), last)
    t0 = first.frameray.time or 0.0
    t1 = last.frameray.time or 0.0
    return (f"PSNR {fmt(first.psnr, '{:.1f}')} dB at {first.label} → {fmt(last.psnr, '{:.1f}')} dB"
            f" at {last.label}; time {t0:.2f} → {t1:.2f} s; converged (isolated PSNR ≥ 54 dB)"
            f" from {enough.label}")


def write_csv(study, path):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["scene", "knob", "setting", "switches", "frameray_render_cpu_s", "frameray_frame_wall_s",
                    "frameray_process_cpu_s", "frameray_process_wall_s", "povray_render_cpu_s",
                    "povray_render_wall_s", "rmse", "psnr_db", "within_4_255",
                    "isolated_psnr_db", "povray_psnr_db", "povray_within_4_255", "error"])
        for p in study.points + [point for _, point in study.presets]:
            pov = p.povray or Render()
            w.writerow([study.scene.stem, p.knob, p.label, " ".join(p.switches),
                        fmt(p.frameray.time, "{:.3f}", ""), fmt(p.frameray.frame_wall, "{:.3f}", ""),
                        fmt(p.frameray.cpu, "{:.3f}", ""), fmt(p.frameray.wall, "{:.3f}", ""),
                        fmt(pov.time, "{:.3f}", ""), fmt(pov.frame_wall, "{:.3f}", ""),
                        fmt(p.rmse, "{:.4f}", ""), fmt(p.psnr, "{:.2f}", ""),
                        fmt(p.within, "{:.5f}", ""), fmt(p.isolated_psnr, "{:.2f}", ""),
                        fmt(p.povray_psnr, "{:.2f}", ""), fmt(p.povray_within, "{:.5f}", ""),
                        p.frameray.error or (pov.error if p.povray else "")])


def write_plot(study, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import matplotlib.ticker
    except ImportError:
        print("accuracy_study: matplotlib missing, no plot (bash scripts/setup.sh)",
              file=sys.stderr)
        return False
    fig, ax = plt.subplots(figsize=(8, 5.5), dpi=100)
    markers = "osD^v<>ph*X"
    for i, knob_name in enumerate(study.knobs):
        sweep = [p for p in study.points if p.knob == knob_name
                 and p.frameray.time is not None and p.psnr is not None]
        if not sweep:
            continue
        xs = [p.frameray.time for p in sweep]
        ys = [psnr_value(p.psnr) for p in sweep]
        ax.plot(xs, ys, marker=markers[i % len(markers)], label=KNOBS[knob_name].title,
                alpha=0.8)
        for p, x, y in zip(sweep, xs, ys):
            ax.annotate(p.label, (x, y), textcoords="offset points", xytext=(3, 3), fontsize=7)
    base = [p for p in study.points if p.switches == merge(study.baseline, [])
            and p.frameray.time is not None and p.psnr is not None]
    if base:
        ax.scatter([base[0].frameray.time], [psnr_value(base[0].psnr)], marker="*", s=200,
                   color="gold", edgecolors="black", label="baseline", zorder=6)
    for name, p in study.presets:
        if p.frameray.time is not None and p.psnr is not None:
            ax.scatter([p.frameray.time], [psnr_value(p.psnr)], marker="P", s=140,
                       color="crimson", edgecolors="black", zorder=7)
            ax.annotate(f"preset {name}", (p.frameray.time, psnr_value(p.psnr)),
                        textcoords="offset points", xytext=(6, -10), fontsize=8,
                        color="crimson")
    front = pareto(study.points)
    if front:
        ax.step([p.frameray.time for p in front], [psnr_value(p.psnr) for p in front],
                where="post", color="black", linewidth=1, linestyle=":")
        ax.scatter([p.frameray.time for p in front], [psnr_value(p.psnr) for p in front],
                   s=120, facecolors="none", edgecolors="black", label="Pareto front", zorder=5)
    for name, budget in BUDGETS:
        ax.axhline(budget, color="grey", linestyle="--", linewidth=0.7)
        ax.text(0.01, budget, f"{name} ≥ {budget:.0f} dB",
                fontsize=7, color="grey", va="bottom", transform=ax.get_yaxis_transform())
    ax.set_xscale("log")
    ax.xaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
    ax.xaxis.set_minor_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
    ax.tick_params(axis="x", which="minor", labelsize=7)
    ax.set_xlabel("frameray render CPU time, s (log scale; best of runs, start-up excluded)")
    ax.set_ylabel(f"PSNR vs converged reference, dB ({PSNR_CAP:.0f} = identical)")
    ax.set_title(f"{study.scene.stem}: accuracy vs time, one knob at a time from the baseline")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
    return True


def write_report(study, path, plot_name, args, started, load):
    ref = study.reference
    lines = [
        f"# Accuracy–time study: `{study.scene.stem}`",
        "",
        *[f"> {d}" for d in study.description if d],
        "",
        f"- date: {started.isoformat(timespec='seconds')}; machine: {machine_description()}; "
        f"load average at start: {load} (a shared machine: times are indicative)",
        f"- frameray `{args.frameray}`; povray: {args.povray_version}",
        f"- size {args.width}x{args.height}, {args.threads} render thread(s) (+WT) for both; "
        "time = CPU seconds of the render (the machine is shared, so CPU time is "
        "steadier than wall time), per frame of a run that renders the same frame "
        f"{args.frames} times: for frameray the best of {args.reps} run(s) of its "
        "process CPU (user + sys) minus its start-up CPU "
        f"({args.startup_cpu:.2f} s, measured on an empty 1x1 scene); for povray one run, "
        "the CPU-seconds it reports for parse + bounding + trace. Wall columns: "
        "the mean frame time each program reports",
        f"- baseline: `{' '.join(study.baseline)}`",
        f"- converged reference (frameray): `{' '.join(study.reference_switches)}`, "
        f"{ref.time:.2f} CPU s",
        "- error of each frameray image against the reference: RMSE (0..255), PSNR (dB, "
        f"{PSNR_CAP:.0f} = identical), fraction of pixels within 4/255; *isolated* PSNR is "
        "against the sweep's own most accurate setting (the one closest to the "
        "reference: the knob's effect alone); *povray PSNR* compares povray's image at "
        "the same setting with frameray's reference",
        "",
        f"![time vs error]({plot_name})",
        "",
        "## Recommendation: presets (all knobs combined, rendered and measured)",
        "",
        "Each knob at its cheapest swept setting whose own (isolated) error clears the "
        "budget with a margin, all combined and rendered to check the total error.",
        "",
        "| preset | PSNR ≥ | switches | frameray CPU s | povray CPU s | PSNR dB | "
        "within 4/255 | speed-up vs reference | meets budget |",
        "|---|---:|---|---:|---:|---:|---:|---:|---|",
    ]
    for (name, budget), (_, p) in zip(BUDGETS, study.presets):
        pov = p.povray or Render()
        t = p.frameray.time
        lines.append(f"| {name} | {budget:.0f} | `{' '.join(p.switches)}` | {fmt(t, '{:.2f}')} | "
                     f"{fmt(pov.time, '{:.2f}')} | {fmt(p.psnr, '{:.1f}')} | "
                     f"{fmt(p.within, '{:.4f}')} | "
                     f"{(ref.time / max(t, 1e-3)) if t is not None else 0:.1f}× | "
                     f"{'yes' if p.psnr is not None and psnr_value(p.psnr) >= budget else 'no'} |")
    lines += [
        "",
        "## Cheapest single measured setting within each budget (one knob changed)",
        "",
        "| budget | PSNR ≥ | setting (changes from the baseline) | frameray CPU s | PSNR dB | "
        "within 4/255 | speed-up vs reference |",
        "|---|---:|---|---:|---:|---:|---:|",
    ]
    for name, budget in BUDGETS:
        p = cheapest_within(study.points, budget)
        if p is None:
            lines.append(f"| {name} | {budget:.0f} | none measured reaches it | | | | |")
            continue
        lines.append(f"| {name} | {budget:.0f} | `{setting_text(p, study)}` ({p.knob} = "
                     f"{p.label}) | {p.frameray.time:.2f} | {fmt(p.psnr, '{:.1f}')} | "
                     f"{fmt(p.within, '{:.4f}')} | {ref.time / max(p.frameray.time, 1e-3):.1f}× |")
    lines += ["", "## Findings per knob", ""]
    for knob_name in study.knobs:
        lines.append(f"- **{KNOBS[knob_name].title}**: {knob_finding(study, knob_name)}")
    front = pareto(study.points)
    lines += ["", "Pareto front (no other measured setting is both faster and more accurate): "
              + ", ".join(f"{p.knob}={p.label} ({p.frameray.time:.2f} s, "
                          f"{fmt(p.psnr, '{:.1f}')} dB)" for p in front), ""]
    lines += ["## All measurements", "",
              "| knob | setting | frameray CPU s | frameray wall s | povray CPU s | "
              "povray wall s | RMSE | PSNR dB | within 4/255 | isolated PSNR | povray PSNR | "
              "error |",
              "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"]
    for p in study.points:
        pov = p.povray or Render()
        err = (p.frameray.error or (pov.error if p.povray else "")).replace("|", "\\|")
        lines.append(f"| {p.knob} | {p.label} | {fmt(p.frameray.time, '{:.2f}')} | "
                     f"{fmt(p.frameray.frame_wall, '{:.2f}')} | {fmt(pov.time, '{:.2f}')} | "
                     f"{fmt(pov.frame_wall, '{:.2f}')} | {fmt(p.rmse, '{:.2f}')} | "
                     f"{fmt(p.psnr, '{:.1f}')} | {fmt(p.within, '{:.4f}')} | "
                     f"{fmt(p.isolated_psnr, '{:.1f}')} | {fmt(p.povray_psnr, '{:.1f}')} | {err} |")
    lines += ["", f"Regenerate: `tests/bench/accuracy_study.py {study.scene.relative_to(REPO_ROOT)}"
              f" --out {Path(args.out).resolve().relative_to(REPO_ROOT) if Path(args.out).resolve().is_relative_to(REPO_ROOT) else args.out}`"
              " (or `--run-all` for every study scene).", ""]
    Path(path).write_text("\n".join(lines))


def write_summary(studies, out, args, started, load):
    lines = [
        "# Accuracy–time study: summary",
        "",
        f"- date: {started.isoformat(timespec='seconds')}; machine: {machine_description()}; "
        f"load average at start: {load} (shared machine: times are indicative)",
        f"- povray: {args.povray_version}; size {args.width}x{args.height}; "
        f"{args.threads} render thread(s) for both; times are CPU seconds per frame "
        f"({args.frames} frames per run)",
        "- budgets: " + ", ".join(f"{n} PSNR ≥ {b:.0f} dB" for n, b in BUDGETS) +
        " against each scene's converged frameray reference",
        "- regenerate: `tests/bench/accuracy_study.py --run-all`",
        "",
        "Presets per scene (changes from the scene's baseline; frameray CPU s per frame; "
        "PSNR against the reference):",
        "",
        "| scene | knobs | baseline CPU s | baseline PSNR | reference CPU s | draft | preview "
        "| final |",
        "|---|---|---:|---:|---:|---|---|---|",
    ]
    for s in studies:
        base = next((p for p in s.points if not [x for x in p.switches if x not in s.baseline]),
                    None)
        cells = []
        for (_, budget), (_, p) in zip(BUDGETS, s.presets):
            met = p.psnr is not None and psnr_value(p.psnr) >= budget
            cells.append(f"`{setting_text(p, s)}`: {fmt(p.frameray.time, '{:.2f}')} s, "
                         f"{fmt(p.psnr, '{:.1f}')} dB" + ("" if met else " (misses)"))
        lines.append(f"| [{s.scene.stem}]({s.scene.stem}.md) | {', '.join(s.knobs)} | "
                     f"{fmt(base.frameray.time if base else None, '{:.2f}')} | "
                     f"{fmt(base.psnr if base else None, '{:.1f}')} | {s.reference.time:.2f} | "
                     + " | ".join(cells) + " |")
    lines += ["", "## Knobs across scenes", ""]
    for s in studies:
        for k in s.knobs:
            lines.append(f"- {s.scene.stem} / {KNOBS[k].title}: {knob_finding(s, k)}")
    lines += ["", "## A Render_Budget rule?", ""]
    lines += budget_rule(studies)
    Path(out / "README.md").write_text("\n".join(lines) + "\n")


def budget_rule(studies):
    """For knobs swept in several scenes: the loosest setting whose isolated
    PSNR (the knob's own error, against its most accurate swept setting) met
    each budget in every one of them."""
    lines = ["Per knob swept in several scenes: the loosest setting whose own error "
             "(isolated PSNR, against the knob's most accurate swept setting, the other "
             "knobs at the baseline) met each budget in every scene that sweeps it. A "
             "`Render_Budget` option could map a budget to these settings; the rule rests "
             "only on the scenes listed, at 320x240.", ""]
    by_knob = {}
    for s in studies:
        for k in s.knobs:
            by_knob.setdefault(k, []).append(s)
    for k, scenes in by_knob.items():
        rows = []
        for name, budget in BUDGETS:
            labels = []
            for s in scenes:
                sweep = [p for p in s.points if p.knob == k]
                ok = [i for i, p in enumerate(sweep)
                      if p.isolated_psnr is not None and psnr_value(p.isolated_psnr) >= budget]
                labels.append(sweep[min(ok)].label if ok else None)
            if all(labels):
                # The values are ordered from cheapest to most accurate, so
                # the latest index over the scenes is the safe choice.
                order = [lbl for lbl, _ in KNOBS[k].values]
                safest = max(labels, key=order.index)
                rows.append(f"{name}: {safest}")
            else:
                rows.append(f"{name}: not reachable with this knob alone in "
                            f"{sum(1 for l in labels if l is None)} of {len(scenes)} scene(s)")
        lines.append(f"- {KNOBS[k].title} (scenes: {', '.join(s.scene.stem for s in scenes)}): "
                     + "; ".join(rows))
    return lines


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene", nargs="?", help="study scene (.pov with study-* header lines)")
    parser.add_argument("--run-all", action="store_true",
                        help=f"every scene in {SCENES_DIR.relative_to(REPO_ROOT)}")
    parser.add_argument("--knobs", type=lambda s: [k for k in s.split(",") if k],
                        help="comma-separated knobs instead of the scene's study-knobs: "
                        + ", ".join(KNOBS))
    parser.add_argument("--out", default=None, help=f"output folder (default {DEFAULT_OUT})")
    parser.add_argument("--reps", type=int, default=1, help="frameray runs per setting (best)")
    parser.add_argument("--frames", type=int, default=4,
                        help="identical frames per run; times are per frame")
    parser.add_argument("--no-povray", action="store_true", help="skip povray's timings")
    parser.add_argument("--threads", type=int, default=1,
                        help="render threads of both programs (+WT); 1 keeps times steady "
                        "on a shared machine")
    parser.add_argument("--width", type=int, default=320)
    parser.add_argument("--height", type=int, default=240)
    parser.add_argument("--timeout", type=float, default=600.0)
    parser.add_argument("--frameray", default=str(REPO_ROOT / "build/bin/frameray"))
    parser.add_argument("--povray", default="povray")
    args = parser.parse_args(argv)
    if not args.run_all and not args.scene:
        parser.error("give a SCENE or --run-all")
    args.out = args.out or str(DEFAULT_OUT)
    args.frameray = str(Path(args.frameray).resolve())
    return args


def main(argv):
    args = parse_args(argv)
    if not Path(args.frameray).exists():
        sys.exit(f"accuracy_study: {args.frameray} not found (bash scripts/build.sh)")
    args.povray_version = program_version([args.povray, "--version"])
    scenes = sorted(SCENES_DIR.glob("*.pov")) if args.run_all else [Path(args.scene).resolve()]
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    started = datetime.datetime.now().astimezone()
    load = " ".join(Path("/proc/loadavg").read_text().split()[:3])
    studies = []
    with tempfile.TemporaryDirectory(prefix="frameray-accuracy.") as scratch:
        args.startup_cpu = startup_cpu(args, scratch)
        print(f"accuracy_study: frameray start-up CPU {args.startup_cpu:.2f} s", file=sys.stderr)
        for scene in scenes:
            study = run_study(scene, args, scratch)
            stem = scene.stem
            write_csv(study, out / f"{stem}.csv")
            plotted = write_plot(study, out / f"{stem}.png")
            write_report(study, out / f"{stem}.md", f"{stem}.png" if plotted else "", args,
                         started, load)
            print(f"accuracy_study: wrote {out / stem}.csv/.png/.md", file=sys.stderr)
            studies.append(study)
    if args.run_all:
        write_summary(studies, out, args, started, load)
        print(f"accuracy_study: wrote {out / 'README.md'}", file=sys.stderr)


if __name__ == "__main__":
    main(sys.argv[1:])
