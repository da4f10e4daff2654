#!/usr/bin/env python3
"""Times frameray against the reference POV-Ray 3.7 on the same scenes.

    tests/bench/bench.py [--reps N] [--frameray PATH] [--povray PATH]
                         [--out results.md] ENTRY... [-- extra switches]

ENTRY is a suite file (one "path switches..." entry per line, paths relative
to the repository root, '#' comments) or a scene .pov / .ini file. Every
entry is rendered by both programs with the same switches, alternating
frameray, povray, frameray, ... so that slow drifts of the machine (thermal
throttling, background load) affect both equally. Per run it records wall
time, CPU time (user + sys) and peak resident memory of that child process,
and reports medians as a markdown table. Uses the standard library only.
"""

import argparse
import datetime
import os
import platform
import shlex
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parents[2]

# povray warns about this on every run when ~/.povray/3.7/povray.conf does
# not exist; it is never the reason a run failed.
BENIGN_STDERR = ("cannot open the user configuration file",)


@dataclass
class Entry:
    path: Path  # scene or INI file, absolute
    switches: list  # POV-Ray switches for this entry
    label: str  # how the entry is named in the report


@dataclass
class Run:
    wall: float  # seconds
    cpu: float  # user + sys seconds of the child
    peak_mib: float  # ru_maxrss of the child
    exit_code: int
    message: str = ""  # first useful stderr line when the run failed


@dataclass
class Result:
    entry: Entry
    runs: dict = field(default_factory=lambda: {"frameray": [], "povray": []})
    match: float = None  # frameray's last image against povray's (--match)


def parse_args(argv):
    # Everything after a bare "--" goes to the renderers, not to argparse.
    if "--" in argv:
        split = argv.index("--")
        argv, extra = argv[:split], argv[split + 1:]
    else:
        extra = []
    parser = argparse.ArgumentParser(
        description="Benchmark frameray against povray on the same scenes.",
        epilog="Switches after '--' are passed to both renderers for every entry.")
    parser.add_argument("--reps", type=int, default=3,
                        help="runs per renderer and entry (default 3, at least 1)")
    parser.add_argument("--frameray", default=str(REPO_ROOT / "build" / "bin" / "frameray"),
                        help="frameray binary (default: build/bin/frameray in the repo)")
    parser.add_argument("--povray", default=shutil.which("povray") or "povray",
                        help="reference povray binary (default: povray on PATH)")
    parser.add_argument("--out", type=Path, help="also write the markdown report here")
    parser.add_argument("--match", action="store_true",
                        help="also compare frameray's image with povray's (the conformance "
                             "metric: fraction of pixels within 4/255) and report it")
    parser.add_argument("entries", nargs="+", metavar="ENTRY",
                        help="suite file, or scene .pov / .ini file")
    args = parser.parse_args(argv)
    if args.reps < 1:
        parser.error("--reps must be at least 1")
    # Renders run in each entry's folder, where a relative program path
    # would no longer resolve; bare names are still looked up on PATH.
    for name in ("frameray", "povray"):
        program = getattr(args, name)
        if os.sep in program:
            setattr(args, name, str(Path(program).resolve()))
    args.extra = extra
    return args


def read_suite(path):
    """Entries of a suite file: 'relative/path switches...' per line."""
    entries = []
    with open(path, encoding="utf-8") as suite:
        for number, line in enumerate(suite, 1):
            words = shlex.split(line, comments=True)
            if not words:
                continue
            scene = REPO_ROOT / words[0]
            if not scene.is_file():
                sys.exit(f"bench: {path}:{number}: no such scene {scene}")
            entries.append(Entry(scene, words[1:], " ".join(words)))
    return entries


def collect_entries(names):
    entries = []
    for name in names:
        path = Path(name)
        if not path.is_file():
            sys.exit(f"bench: no such file: {name}")
        if path.suffix.lower() in (".pov", ".ini"):
            entries.append(Entry(path.resolve(), [], name))
        else:
            entries.extend(read_suite(path))
    return entries


def first_useful_line(stderr_path):
    """The line most likely to say why a run failed: the first mentioning an
    error, else the first non-benign non-empty line."""
    try:
        lines = Path(stderr_path).read_text(errors="replace").splitlines()
    except OSError:
        return ""
    lines = [l.strip() for l in lines
             if l.strip() and not any(b in l for b in BENIGN_STDERR)]
    for line in lines:
        if "error" in line.lower():
            return line
    return lines[0] if lines else ""


def run_once(command, cwd, stderr_path):
    """Runs one render and measures that child alone (not this script)."""
    with open(stderr_path, "wb") as stderr:
        start = time.perf_counter()
        try:
            child = subprocess.Popen(command, cwd=cwd, stdin=subprocess.DEVNULL,
                                     stdout=subprocess.DEVNULL, stderr=stderr)
        except OSError as error:
            return Run(0.0, 0.0, 0.0, 127, f"cannot start {command[0]}: {error}")
        # wait4 instead of child.wait() to get this child's own rusage.
        _, status, usage = os.wait4(child.pid, 0)
        wall = time.perf_counter() - start
    child.returncode = os.waitstatus_to_exitcode(status)
    run = Run(wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024.0,
              child.returncode)  # ru_maxrss is in KiB on Linux
    if run.exit_code != 0:
        run.message = first_useful_line(stderr_path)
    return run


def clear_directory(directory):
    for item in directory.iterdir():
        if item.is_dir():
            shutil.rmtree(item)
        else:
            item.unlink()


def benchmark(entry, args, scratch):
    result = Result(entry)
    switches = entry.switches + args.extra
    # Running in the entry's folder lets relative #include and
    # Input_File_Name paths in INI files resolve the same way for both.
    cwd = entry.path.parent
    commands = {
        "frameray": [args.frameray, str(entry.path)] + switches,
        "povray": [args.povray, str(entry.path), "-D"] + switches,
    }
    for rep in range(args.reps):
        for renderer in ("frameray", "povray"):
            out_dir = scratch / "out"
            out_dir.mkdir(exist_ok=True)
            # Fresh output folder every run, so nothing is ever "continued"
            # from, or mistaken for, an earlier run's image.
            clear_directory(out_dir)
            command = commands[renderer] + [f"+O{out_dir / 'render.png'}"]
            run = run_once(command, cwd, scratch / "stderr.txt")
            result.runs[renderer].append(run)
            image = out_dir / "render.png"
            if args.match and run.exit_code == 0 and image.is_file():
                shutil.copyfile(image, scratch / f"{renderer}.png")
            state = "ok" if run.exit_code == 0 else f"exit {run.exit_code}"
            print(f"  {renderer:8} rep {rep + 1}/{args.reps}: {run.wall:7.3f} s wall, "
                  f"{run.cpu:7.3f} s CPU, {run.peak_mib:7.1f} MiB  {state}",
                  file=sys.stderr)
    if args.match:
        result.match = image_match(scratch / "frameray.png", scratch / "povray.png")
        for renderer in ("frameray", "povray"):
            (scratch / f"{renderer}.png").unlink(missing_ok=True)
    return result


def image_match(test, reference):
    """The conformance metric of `test` against `reference`, None when an
    image is missing or cannot be compared."""
    if not (test.is_file() and reference.is_file()):
        return None
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    import png_compare
    try:
        return png_compare.compare_files(str(test), str(reference)).match
    except Exception as error:  # noqa: BLE001 - reported, never fatal
        print(f"bench: cannot compare {test} with {reference}: {error}", file=sys.stderr)
        return None


def summarize(runs):
    """(wall, cpu, peak) medians over successful runs, or None; and the
    failure text when any run failed."""
    good = [r for r in runs if r.exit_code == 0]
    bad = [r for r in runs if r.exit_code != 0]
    medians = None
    if good:
        medians = (statistics.median(r.wall for r in good),
                   statistics.median(r.cpu for r in good),
                   statistics.median(r.peak_mib for r in good))
    failure = ""
    if bad:
        first = bad[0]
        detail = f": {first.message}" if first.message else ""
        failure = f"FAILED {len(bad)}/{len(runs)} (exit {first.exit_code}{detail})"
    return medians, failure


def cell_text(text):
    return text.replace("|", "\\|")


def ratio(a, b):
    return f"{a / b:.2f}" if b > 0 else "n/a"


def machine_description():
    model = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as cpuinfo:
            for line in cpuinfo:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    usable = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else None
    cores = f"{os.cpu_count()} logical CPUs"
    if usable is not None and usable != os.cpu_count():
        cores += f" ({usable} usable)"
    return f"{model}, {cores}, {platform.system()} {platform.release()}"


def program_version(command):
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.TimeoutExpired):
        return "unknown"
    for line in (done.stdout + done.stderr).splitlines():
        if line.strip() and not any(b in line for b in BENIGN_STDERR):
            return line.strip()
    return "unknown"


def report(results, args):
    now = datetime.datetime.now().astimezone()
    lines = [
        "# frameray vs POV-Ray benchmark",
        "",
        f"- date: {now.isoformat(timespec='seconds')}",
        f"- machine: {machine_description()}",
        f"- frameray: `{args.frameray}`",
        f"- povray: `{args.povray}` ({program_version([args.povray, '--version'])})",
        f"- runs: {args.reps} per renderer and entry, alternating; medians shown",
    ]
    if args.extra:
        lines.append(f"- extra switches: `{' '.join(args.extra)}`")
    header = ("| entry | frameray wall s | frameray CPU s | frameray peak MiB "
              "| povray wall s | povray CPU s | povray peak MiB | wall ratio | CPU ratio |")
    rule = "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
    if args.match:
        header += " match |"
        rule += "---:|"
    lines += ["", header, rule]
    notes = []
    cpu_ratios, wall_ratios = [], []
    for result in results:
        row = [f"`{cell_text(result.entry.label)}`"]
        medians = {}
        for renderer in ("frameray", "povray"):
            medians[renderer], failure = summarize(result.runs[renderer])
            if medians[renderer]:
                wall, cpu, peak = medians[renderer]
                row += [f"{wall:.3f}", f"{cpu:.3f}", f"{peak:.1f}"]
            else:
                row += ["FAILED", "", ""]
            if failure:
                notes.append(f"- `{cell_text(result.entry.label)}`, {renderer}: "
                             f"{cell_text(failure)}")
        f, p = medians["frameray"], medians["povray"]
        if f and p:
            row += [ratio(f[0], p[0]), ratio(f[1], p[1])]
            if p[0] > 0 and p[1] > 0 and f[0] > 0 and f[1] > 0:
                wall_ratios.append(f[0] / p[0])
                cpu_ratios.append(f[1] / p[1])
        else:
            row += ["n/a", "n/a"]
        if args.match:
            row.append("n/a" if result.match is None else f"{result.match:.4f}")
        lines.append("| " + " | ".join(row) + " |")
    lines += ["", "Ratios are frameray / povray (below 1 means frameray is faster)."]
    if len(cpu_ratios) > 1:
        lines += ["", f"Geometric mean over {len(cpu_ratios)} entries: wall ratio "
                  f"{statistics.geometric_mean(wall_ratios):.2f}, CPU ratio "
                  f"{statistics.geometric_mean(cpu_ratios):.2f}; highest CPU ratio "
                  f"{max(cpu_ratios):.2f}."]
    if args.match:
        matches = [r.match for r in results if r.match is not None]
        if matches:
            lines += [f"Match (frameray's image against povray's, fraction of pixels within "
                      f"4/255): lowest {min(matches):.4f}; {sum(m >= 0.99 for m in matches)} of "
                      f"{len(matches)} compared at 0.99 or above."]
    if notes:
        lines += ["", "Failed runs (medians above use the successful runs only):", ""] + notes
    return "\n".join(lines) + "\n"


def main():
    args = parse_args(sys.argv[1:])
    entries = collect_entries(args.entries)
    if not entries:
        sys.exit("bench: no entries to run")
    for program in (args.frameray, args.povray):
        if shutil.which(program) is None:
            print(f"bench: warning: '{program}' is not an executable; "
                  "its runs will be reported as failed", file=sys.stderr)

    results = []
    with tempfile.TemporaryDirectory(prefix="frameray-bench-") as scratch:
        for number, entry in enumerate(entries, 1):
            print(f"[{number}/{len(entries)}] {entry.label}", file=sys.stderr)
            results.append(benchmark(entry, args, Path(scratch)))

    text = report(results, args)
    print(text, end="")
    if args.out:
        args.out.write_text(text, encoding="utf-8")
        print(f"bench: report written to {args.out}", file=sys.stderr)


if __name__ == "__main__":
    main()
