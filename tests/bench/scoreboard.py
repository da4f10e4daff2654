#!/usr/bin/env python3
"""The real-corpus scoreboard: every scene of POV-Ray's example corpus, frameray vs povray.

    tests/bench/scoreboard.py [--jobs N] [--only SUBSTRING]... [--update]
                              [--timeout SECONDS] [--povray-only] [--no-write]

Covers the whole of /usr/share/doc/povray/examples: every animation
(animations/*/*.ini) and every portfolio page (portfolio/*.ini) from its own
INI file, so its anti-aliasing, clock, frame range and (portfolio) image size
apply to both programs; advanced/desk from desk.ini (its last frame shows the
first frames' images); every other .pov as a still at 160x120 with -A. Each
program runs in its own temporary copy of the scene's folder (scenes write
files), niced; frameray gets POVINI=/dev/null, povray reads the system
povray.ini (library paths only) with HOME pointing at an empty folder.

povray's results (frames, log, exit status, times) are cached outside the
repository, in ~/.cache/frameray-scoreboard/povray/KEY/ (or
$FRAMERAY_SCOREBOARD_CACHE), KEY hashing the scene folder's content, the
switches and povray's version, so a rerun renders only frameray. frameray's
latest frames are kept in .../frameray/SCENE/ for whoever wants to look.

Per scene: status (rendered, partial, stopped, timeout, crash, povray fails),
frames, mean match of frameray's frames against povray's (the conformance
metric: fraction of pixels within 4/255 on every channel, png_compare.py,
frameray-compare as the fallback; a frame frameray did not write counts 0),
wall and CPU time of each run, and frameray's first error. povray renders with one thread (+WT1, --povray-threads):
with more, its radiosity, area-light jitter and crand images change from run to
run and with the thread count, so only its one-thread image is a fixed
reference (frameray's images do not depend on its thread count). Scenes that stop on
radiosity, media or photons are grouped under those names. The report
(DIR/scoreboard-latest.md and a dated copy) has the totals, a histogram of
first errors (normalised: numbers and quoted names folded), the scenes povray
itself cannot render, and the per-scene table; DIR/scoreboard-latest.json and
.csv carry the same rows for other tools.

With --only, only the matching scenes are rendered and their before/after
against scoreboard-latest.json is printed; --update merges them into it.
"""

import os
import sys

# numpy (Debian's, in /usr/bin/python3) makes the image comparison ~50x faster.
import importlib.util  # noqa: E402

if importlib.util.find_spec("numpy") is None:
    if os.path.exists("/usr/bin/python3") and os.path.realpath(sys.executable) != \
            os.path.realpath("/usr/bin/python3") and not os.environ.get("SCOREBOARD_REEXEC"):
        os.environ["SCOREBOARD_REEXEC"] = "1"
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)

import argparse  # noqa: E402
import concurrent.futures  # noqa: E402
import csv  # noqa: E402
import datetime  # noqa: E402
import hashlib  # noqa: E402
import json  # noqa: E402
import re  # noqa: E402
import shutil  # noqa: E402
import subprocess  # noqa: E402
import tempfile  # noqa: E402
import threading  # noqa: E402
import time  # noqa: E402
import zlib  # noqa: E402
from dataclasses import asdict, dataclass, field  # noqa: E402
from pathlib import Path  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench import machine_description, program_version  # noqa: E402
import png_compare  # noqa: E402

REPO_ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = Path("/usr/share/doc/povray/examples")
CACHE_FORMAT = 1  # bump when the cached record changes

# Scenes outside animations/ and portfolio/ that only make sense through their
# own INI file (desk's last frame frames the images its first frames wrote).
SCENE_INIS = {"advanced/desk/desk.pov": "desk.ini"}

# Why povray cannot render a scene, where its own log does not say it plainly.
POVRAY_FAILURE_NOTES = {
    "advanced/cliche/cliche.pov": "needs sign.pov's output (sign.tga) rendered first",
    "incdemo/sort.pov": "needs arial.ttf, which povray does not ship",
    "portfolio/__empty.ini": "a template page with no content",
}

# First errors that belong to another issue's feature, by pattern.
GROUPS = [
    ("radiosity", re.compile(r"radiosity", re.I)),
    ("photons", re.compile(r"photons?\b", re.I)),
    ("media", re.compile(r"\bmedia\b", re.I)),
]

IMAGE_SUFFIXES = (".png", ".tga", ".ppm", ".bmp", ".exr", ".hdr", ".jpg")
MATCH_RE = re.compile(r"match ([0-9.]+)")
GOOD_MATCH = 0.99


@dataclass
class Run:
    wall: float = 0.0
    cpu: float = 0.0
    exit_code: int = 0
    timed_out: bool = False
    frames: dict = field(default_factory=dict)  # file name -> Path
    log: str = ""


@dataclass
class Entry:
    kind: str  # animation, portfolio, ini, still
    name: str  # path relative to the examples folder
    folder: Path
    switches: list


@dataclass
class Row:
    kind: str
    scene: str
    status: str  # rendered, partial, stopped, timeout, crash, povray fails
    group: str  # radiosity, media, photons or "" for the rest
    povray_frames: int
    frameray_frames: int
    match: float | None  # mean over povray's frames
    min_match: float | None
    povray_wall: float
    povray_cpu: float
    frameray_wall: float
    frameray_cpu: float
    first_error: str
    povray_error: str
    povray_dir: str  # cached povray frames
    frameray_dir: str  # frameray's latest frames


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
    parser.add_argument("--update", action="store_true",
                        help="with --only: merge the new rows into the latest results")
    parser.add_argument("--jobs", type=int, default=1, help="scenes rendered at once")
    parser.add_argument("--threads", type=int, default=0,
                        help="render threads per program (+WTn for both); 0 = their default")
    parser.add_argument("--povray-threads", type=int, default=1,
                        help="povray's render threads (+WTn, in its cache key); 0 = its "
                        "default. One thread is its only deterministic image")
    parser.add_argument("--nice", type=int, default=10, help="nice(1) level of every render")
    parser.add_argument("--timeout", type=float, default=300.0,
                        help="seconds per frameray run before it is killed (at least 3 "
                        "times povray's wall time)")
    parser.add_argument("--povray-timeout", type=float, default=1800.0,
                        help="seconds per povray run (cached, so it runs once)")
    parser.add_argument("--povray-only", action="store_true",
                        help="only fill povray's cache, render nothing with frameray")
    parser.add_argument("--cache", default=os.environ.get(
        "FRAMERAY_SCOREBOARD_CACHE", str(Path.home() / ".cache/frameray-scoreboard")))
    parser.add_argument("--out-dir", default=str(REPO_ROOT / "tests/bench/results"))
    parser.add_argument("--no-write", action="store_true",
                        help="print the table only, write no file")
    return parser.parse_args(argv)


# ---------------------------------------------------------------- the corpus


def entries(args):
    """Every scene of the corpus, in a stable order."""
    examples = Path(args.examples)
    size = [f"+W{args.width}", f"+H{args.height}"]
    threads = [f"+WT{args.threads}"] if args.threads > 0 else []
    found = []
    # The INI comes last so that its own settings (portfolio: image size) win.
    for kind, pattern in (("animation", "animations/*/*.ini"), ("portfolio", "portfolio/*.ini")):
        for ini in sorted(examples.glob(pattern)):
            name = str(ini.relative_to(examples))
            found.append(Entry(kind, name, ini.parent, ["-D"] + size + threads + [ini.name]))
    for scene in sorted(examples.rglob("*.pov")):
        name = str(scene.relative_to(examples))
        if name.startswith(("animations/", "portfolio/")):
            continue
        if name in SCENE_INIS:
            found.append(Entry("ini", name, scene.parent,
                               ["-D"] + size + threads + [SCENE_INIS[name]]))
        else:
            found.append(Entry("still", name, scene.parent,
                               ["-D", "-A"] + size + threads + [scene.name]))
    if args.only:
        found = [e for e in found if any(o in e.name for o in args.only)]
    return found


_folder_digests = {}
_folder_lock = threading.Lock()


def folder_digest(folder):
    """Hash of every file name and content under folder (scenes read siblings)."""
    with _folder_lock:
        if folder in _folder_digests:
            return _folder_digests[folder]
    digest = hashlib.sha256()
    for path in sorted(p for p in folder.rglob("*") if p.is_file()):
        digest.update(str(path.relative_to(folder)).encode() + b"\0")
        digest.update(path.read_bytes())
    value = digest.hexdigest()
    with _folder_lock:
        _folder_digests[folder] = value
    return value


# ---------------------------------------------------------------- running


def file_states(folder):
    return {p.name: (p.stat().st_mtime_ns, p.stat().st_size) for p in folder.iterdir()
            if p.is_file()}


def image_files(folder, before):
    """Images in folder that the run wrote: new ones, and rewritten ones (the
    example advanced/crater/crater_dat.pov renders the crater_dat.png its
    folder ships)."""
    return {p.name: p for p in folder.iterdir()
            if p.is_file() and p.suffix.lower() in IMAGE_SUFFIXES
            and before.get(p.name) != (p.stat().st_mtime_ns, p.stat().st_size)}


def run_renderer(command, cwd, env, timeout):
    """Runs one renderer in cwd; measures wall and CPU time of that child."""
    before = file_states(cwd)
    log_path = cwd.parent / f"{cwd.name}-log.txt"
    run = Run()
    with open(log_path, "wb") as log:
        start = time.perf_counter()
        child = subprocess.Popen(command, cwd=cwd, env=env, stdin=subprocess.DEVNULL,
                                 stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
        deadline = start + timeout
        while True:
            pid, status, usage = os.wait4(child.pid, os.WNOHANG)
            if pid:
                break
            if time.perf_counter() > deadline:
                os.killpg(child.pid, 9)
                _, status, usage = os.wait4(child.pid, 0)
                run.timed_out = True
                break
            time.sleep(0.02)
        run.wall = time.perf_counter() - start
    child.returncode = os.waitstatus_to_exitcode(status)
    run.exit_code = child.returncode
    run.cpu = usage.ru_utime + usage.ru_stime
    run.frames = image_files(cwd, before)
    run.log = log_path.read_text(errors="replace")
    if run.timed_out:
        run.log += f"\nerror: killed by the scoreboard after {timeout:.0f} s\n"
    return run


def fresh_copy(folder, where):
    shutil.rmtree(where, ignore_errors=True)
    shutil.copytree(folder, where)
    return where


def povray_switches(entry, args):
    """povray's switches: the entry's, with its thread count first (the INI stays last)."""
    if args.povray_threads > 0 and args.threads == 0:
        return [f"+WT{args.povray_threads}"] + entry.switches
    return entry.switches


def povray_key(entry, args, version):
    text = json.dumps([CACHE_FORMAT, folder_digest(entry.folder), entry.name,
                       povray_switches(entry, args), version])
    return hashlib.sha256(text.encode()).hexdigest()[:24]


def povray_run(entry, args, version, scratch):
    """povray's run of entry, from the cache or rendered (and cached) now."""
    slot = Path(args.cache) / "povray" / povray_key(entry, args, version)
    record_path = slot / "run.json"
    if record_path.exists():
        record = json.loads(record_path.read_text())
        if not record["timed_out"] or record["timeout"] >= args.povray_timeout:
            run = Run(record["wall"], record["cpu"], record["exit_code"], record["timed_out"],
                      {n: slot / "frames" / n for n in record["frames"]}, record["log"])
            return run, slot
    copy = fresh_copy(entry.folder, scratch / "povray")
    home = scratch / "home"
    home.mkdir(exist_ok=True)
    env = dict(os.environ, HOME=str(home))
    command = ["nice", "-n", str(args.nice), args.povray] + povray_switches(entry, args)
    run = run_renderer(command, copy, env, args.povray_timeout)
    shutil.rmtree(slot, ignore_errors=True)
    (slot / "frames").mkdir(parents=True)
    for name, path in run.frames.items():
        shutil.copyfile(path, slot / "frames" / name)
    run.frames = {n: slot / "frames" / n for n in run.frames}
    record = {"scene": entry.name, "switches": povray_switches(entry, args), "povray": version,
              "wall": run.wall, "cpu": run.cpu, "exit_code": run.exit_code,
              "timed_out": run.timed_out, "timeout": args.povray_timeout,
              "frames": sorted(run.frames), "log": run.log}
    record_path.write_text(json.dumps(record, indent=1))
    return run, slot


def frameray_run(entry, args, scratch, povray_wall):
    copy = fresh_copy(entry.folder, scratch / "frameray")
    env = dict(os.environ, POVINI="/dev/null")
    command = ["nice", "-n", str(args.nice), args.frameray] + entry.switches
    # A scene povray needs long for may take frameray long too: the limit
    # is for hangs, not for slow renders.
    run = run_renderer(command, copy, env, max(args.timeout, 3 * povray_wall))
    keep = Path(args.cache) / "frameray" / entry.name.replace("/", "+")
    shutil.rmtree(keep, ignore_errors=True)
    keep.mkdir(parents=True)
    for name, path in run.frames.items():
        shutil.copyfile(path, keep / name)
    (keep / "log.txt").write_text(run.log)
    run.frames = {n: keep / n for n in run.frames}
    return run, keep


# ---------------------------------------------------------------- judging


def first_error(log):
    """A program's first `not supported yet: ...` or `error: ...` line, without
    the file:line prefix (the file is usually an include, named in the log)."""
    for line in log.splitlines():
        for marker in ("not supported yet:", "error:", "Parse Error:", "Fatal error"):
            at = line.find(marker)
            if at >= 0:
                text = line[at:]
                if text.startswith("error: not supported yet:"):
                    text = text[len("error: "):]
                return text.strip()[:160]
    return ""


def povray_error(log):
    """povray's reason for failing: its `Parse Error` line and the line after."""
    lines = log.splitlines()
    for i, line in enumerate(lines):
        if "Parse Error" in line or "Fatal error" in line or "Possible Parse Error" in line:
            rest = " ".join(x.strip() for x in lines[i:i + 2] if x.strip())
            return rest[:160]
    return ""


def normalise(error):
    """Folds what varies between occurrences of one error: numbers, strings and
    the scene's own names (quoted text after `identifier`, or with a capital
    letter or digit in it); keywords and symbols stay (`'function' in an
    expression`, `expected ')'`)."""
    def fold(match):
        quoted = match.group(2)
        if match.group(1) or re.search(r"[A-Z0-9]", quoted):
            return f"{match.group(1) or ''}'…'"
        return match.group(0)
    text = re.sub(r"(identifier )?'([^']*)'", fold, error)
    text = re.sub(r'"[^"]*"', '"…"', text)
    return re.sub(r"\b\d+(\.\d+)?\b", "N", text)


def frame_match(compare, test, golden):
    try:
        return png_compare.compare_files(test, golden).match
    except (png_compare.UnsupportedImage, OSError, ValueError, IndexError, zlib.error):
        pass  # e.g. a TGA frame or a size mismatch: let frameray-compare judge
    done = subprocess.run([compare, str(test), str(golden), "--min-match", "0"],
                          capture_output=True, text=True)
    found = MATCH_RE.search(done.stdout)
    return float(found.group(1)) if found else 0.0


def judge(entry, pov, pov_dir, fr, fr_dir, args):
    matches = []
    if fr is not None:
        for frame_name in sorted(pov.frames):
            if frame_name in fr.frames:
                matches.append(frame_match(args.compare, fr.frames[frame_name],
                                           pov.frames[frame_name]))
            else:
                matches.append(0.0)
    error = ""
    status = "povray fails" if not pov.frames else "rendered"
    if fr is None:
        status = "not run" if pov.frames else status
    elif pov.frames:
        if fr.timed_out:
            status = "timeout"
        elif fr.exit_code < 0 or fr.exit_code > 128:
            status = "crash"
        elif fr.exit_code != 0:
            status = "stopped"
        elif not set(pov.frames) <= set(fr.frames):
            status = "partial"
    if fr is not None and (fr.exit_code != 0 or fr.timed_out):
        error = first_error(fr.log) or f"exit {fr.exit_code}"
    group = ""
    if status in ("stopped", "partial"):
        group = next((g for g, pattern in GROUPS if pattern.search(error)), "")
    pov_reason = ""
    if not pov.frames or pov.exit_code != 0:
        pov_reason = POVRAY_FAILURE_NOTES.get(entry.name) or povray_error(pov.log) or \
            (f"did not finish in {pov.wall:.0f} s" if pov.timed_out else f"exit {pov.exit_code}")
    return Row(entry.kind, entry.name, status, group, len(pov.frames),
               len(fr.frames) if fr else 0,
               sum(matches) / len(matches) if matches else None,
               min(matches) if matches else None,
               pov.wall, pov.cpu, fr.wall if fr else 0.0, fr.cpu if fr else 0.0,
               error, pov_reason, str(pov_dir), str(fr_dir) if fr_dir else "")


def score(entry, args, version, scratch_root, index):
    scratch = scratch_root / f"{index:04d}"
    scratch.mkdir()
    pov, pov_dir = povray_run(entry, args, version, scratch)
    fr, fr_dir = (None, None) if args.povray_only else frameray_run(entry, args, scratch,
                                                                    pov.wall)
    row = judge(entry, pov, pov_dir, fr, fr_dir, args)
    shutil.rmtree(scratch, ignore_errors=True)
    return row


# ---------------------------------------------------------------- reporting


def good(row):
    return row.match is not None and row.match >= GOOD_MATCH and row.status == "rendered"


def histogram(rows):
    """(normalised error, count, example scene), most frequent first."""
    counts = {}
    for r in rows:
        if r.status in ("stopped", "partial", "timeout", "crash") and not r.group:
            key = normalise(r.first_error) if r.status != "timeout" else "timeout (hang?)"
            if r.status == "crash":
                key = f"crash: {key}"
            count, example = counts.get(key, (0, r.scene))
            counts[key] = (count + 1, example)
    return sorted(((k, c, e) for k, (c, e) in counts.items()), key=lambda t: (-t[1], t[0]))


def totals(rows):
    renderable = [r for r in rows if r.status != "povray fails"]
    full = [r for r in renderable if r.status == "rendered"]
    good_rows = [r for r in full if good(r)]
    matches_all = [r.match or 0.0 for r in renderable]
    matches_full = [r.match for r in full if r.match is not None]
    pct = (lambda n, d: f"{100.0 * n / d:.1f} %" if d else "n/a")
    mean = (lambda v: f"{sum(v) / len(v):.4f}" if v else "—")
    by_status = {}
    for r in rows:
        by_status[r.status] = by_status.get(r.status, 0) + 1
    groups = {}
    for r in renderable:
        if r.group:
            groups[r.group] = groups.get(r.group, 0) + 1
    return {
        "scenes": len(rows), "povray_renders": len(renderable), "fully_rendered": len(full),
        "good": len(good_rows), "good_pct": pct(len(good_rows), len(renderable)),
        "mean_full": mean(matches_full), "mean_all": mean(matches_all),
        "by_status": by_status, "groups": groups,
        "pov_cpu_full": sum(r.povray_cpu for r in full),
        "fr_cpu_full": sum(r.frameray_cpu for r in full),
    }


def markdown(rows, args, started, load_at_start, version):
    t = totals(rows)
    statuses = ", ".join(f"{k} {v}" for k, v in sorted(t["by_status"].items()))
    groups = ", ".join(f"{k} {v}" for k, v in sorted(t["groups"].items())) or "none"
    ratio = t["fr_cpu_full"] / t["pov_cpu_full"] if t["pov_cpu_full"] else 0.0
    lines = [
        "# Real-corpus scoreboard: POV-Ray 3.7 examples, frameray vs povray",
        "",
        f"- date: {started.isoformat(timespec='seconds')}",
        f"- machine: {machine_description()}; load average at start: {load_at_start}; "
        f"{args.jobs} scene(s) at once, niced",
        f"- frameray: `{args.frameray}` (POVINI=/dev/null, its default threads); povray: "
        f"{version} (cached runs, "
        + (f"+WT{args.povray_threads}: its deterministic image)" if args.povray_threads > 0
           else "its default threads)"),
        f"- stills: `-D -A +W{args.width} +H{args.height} scene.pov`; animations, portfolio "
        f"and advanced/desk: `-D +W{args.width} +H{args.height} their.ini` (the INI's own "
        "settings win: portfolio pages are 200x200 or 100x100 with anti-aliasing)",
        f"- match: mean over povray's frames of the fraction of pixels within 4/255 on every "
        "channel (frameray-compare's metric); a frame frameray did not write counts 0",
        "- times: CPU (user + sys) and wall seconds of each whole run (the machine is "
        "shared, so wall times are rough)",
        "",
        "## Totals",
        "",
        f"- scenes: {t['scenes']}; povray renders {t['povray_renders']}",
        f"- frameray renders fully (exit 0, every frame povray wrote): {t['fully_rendered']}",
        f"- match >= {GOOD_MATCH}: **{t['good']}** ({t['good_pct']} of the scenes povray "
        "renders)",
        f"- mean match over the fully rendered scenes: {t['mean_full']}; over every scene "
        f"povray renders (missing = 0): {t['mean_all']}",
        f"- by status: {statuses}",
        f"- stopped on another issue's feature: {groups}",
        f"- CPU time over the fully rendered scenes: povray {t['pov_cpu_full']:.1f} s, "
        f"frameray {t['fr_cpu_full']:.1f} s (ratio {ratio:.2f})",
        "",
        "## First errors (outside radiosity, media, photons)",
        "",
        "| count | first error (normalised) | example |",
        "|---:|---|---|",
    ]
    for text, count, example in histogram(rows):
        lines.append(f"| {count} | {text.replace('|', chr(92) + '|')} | {example} |")
    lines += ["", "## Scenes povray itself cannot render", ""]
    for r in rows:
        if r.status == "povray fails":
            lines.append(f"- {r.scene}: {r.povray_error.replace('|', chr(92) + '|')}")
    lines += ["", "## Every scene", "",
              "| kind | scene | status | povray frames | frameray frames | mean match | "
              "min match | povray CPU s | frameray CPU s | povray wall s | frameray wall s | "
              "frameray stopped with |",
              "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|"]
    for r in rows:
        match = f"{r.match:.4f}" if r.match is not None else "—"
        low = f"{r.min_match:.4f}" if r.min_match is not None else "—"
        error = r.first_error.replace("|", "\\|")
        lines.append(f"| {r.kind} | {r.scene} | {r.status} | {r.povray_frames} | "
                     f"{r.frameray_frames} | {match} | {low} | {r.povray_cpu:.2f} | "
                     f"{r.frameray_cpu:.2f} | {r.povray_wall:.2f} | {r.frameray_wall:.2f} | "
                     f"{error} |")
    lines += ["", "Regenerate: `tests/bench/scoreboard.py --jobs 2` (build Release first); "
              "machine-readable: scoreboard-latest.json / .csv next to this file.", ""]
    return "\n".join(lines)


def write_results(rows, text, args, started):
    out = Path(args.out_dir)
    out.mkdir(parents=True, exist_ok=True)
    dated = out / f"scoreboard-{started.date().isoformat()}.md"
    dated.write_text(text)
    shutil.copyfile(dated, out / "scoreboard-latest.md")
    payload = {"date": started.isoformat(timespec="seconds"), "totals": totals(rows),
               "rows": [asdict(r) for r in rows]}
    (out / "scoreboard-latest.json").write_text(json.dumps(payload, indent=1) + "\n")
    with open(out / "scoreboard-latest.csv", "w", newline="") as f:
        writer = csv.writer(f)
        names = list(asdict(rows[0]).keys()) if rows else []
        writer.writerow(names)
        for r in rows:
            writer.writerow([getattr(r, n) for n in names])
    print(f"scoreboard: wrote {dated}, scoreboard-latest.md/.json/.csv", file=sys.stderr)


def previous_rows(args):
    path = Path(args.out_dir) / "scoreboard-latest.json"
    if not path.exists():
        return {}
    return {r["scene"]: Row(**r) for r in json.loads(path.read_text())["rows"]}


def progress_line(row):
    match = f"{row.match:.4f}" if row.match is not None else "—"
    return (f"{row.scene}: {row.status}, povray {row.povray_frames} frames "
            f"{row.povray_cpu:.1f}s CPU, frameray {row.frameray_frames} frames "
            f"{row.frameray_cpu:.1f}s CPU, match {match} {row.first_error}")


def render_all(todo, args, version):
    rows = []
    with tempfile.TemporaryDirectory(prefix="frameray-scoreboard.") as scratch:
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            futures = [pool.submit(score, e, args, version, Path(scratch), i)
                       for i, e in enumerate(todo)]
            for future in concurrent.futures.as_completed(futures):
                row = future.result()
                print(progress_line(row), file=sys.stderr, flush=True)
                rows.append(row)
    order = {e.name: i for i, e in enumerate(todo)}
    return sorted(rows, key=lambda r: order[r.scene])


def main(argv):
    args = parse_args(argv)
    tools = [] if args.povray_only else [args.compare, args.frameray]
    for tool in tools:
        if not Path(tool).exists():
            sys.exit(f"scoreboard: {tool} not found (build first: bash scripts/build.sh)")
    args.frameray = str(Path(args.frameray).resolve())
    args.compare = str(Path(args.compare).resolve())
    version = program_version([args.povray, "--version"])
    started = datetime.datetime.now().astimezone()
    load_at_start = " ".join(Path("/proc/loadavg").read_text().split()[:3])
    rows = render_all(entries(args), args, version)
    if args.povray_only:
        return
    if args.only:
        before = previous_rows(args)
        for r in rows:
            old = before.get(r.scene)
            was = f"{old.status} {old.match:.4f}" if old and old.match is not None else \
                (old.status if old else "new")
            now = f"{r.match:.4f}" if r.match is not None else "—"
            print(f"{r.scene}: before {was}; now {r.status} {now} {r.first_error}")
        if not args.update or args.no_write:
            return
        merged = dict(before)
        merged.update({r.scene: r for r in rows})
        everything = entries(argparse.Namespace(**{**vars(args), "only": []}))
        rows = [merged[e.name] for e in everything if e.name in merged]
    text = markdown(rows, args, started, load_at_start, version)
    if args.no_write:
        print(text)
    else:
        write_results(rows, text, args, started)


if __name__ == "__main__":
    main(sys.argv[1:])
