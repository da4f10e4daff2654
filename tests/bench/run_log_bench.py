#!/usr/bin/env python3
"""What the run log costs: the float1 example animation (51 frames) rendered
with Log_Level=off, info (the default) and debug, alternating, medians of
wall and CPU time; the debug run's overhead against the default is what the
log's design promises to keep under 2 %.

    tests/bench/run_log_bench.py [--reps N] [--size WxH] [--frameray PATH] [--out FILE.md]
"""
import argparse
import datetime
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE_DIR = "/usr/share/doc/povray/examples/animations/float1"
LEVELS = ["off", "info", "debug"]


def run(frameray, work, level, size):
    out = os.path.join(work, "frames-" + level)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    cmd = [frameray, "float1.ini", "-V", "+O%s/" % out, "Log_Level=" + level, "Log_Format=json"]
    if size:
        w, h = size.split("x")
        cmd[2:2] = ["+W" + w, "+H" + h]
    env = dict(os.environ, POVINI="/dev/null")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    subprocess.run(cmd, cwd=work, env=env, check=True, stdout=subprocess.DEVNULL)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--size", help="WxH instead of the INI's own (320x240, antialiased)")
    ap.add_argument("--frameray", default=os.path.join(HERE, "..", "..", "build", "bin", "frameray"))
    ap.add_argument("--out")
    a = ap.parse_args()
    frameray = os.path.abspath(a.frameray)
    work = tempfile.mkdtemp(prefix="run_log_bench_")
    for f in os.listdir(SCENE_DIR):
        shutil.copy(os.path.join(SCENE_DIR, f), work)
    times = {level: [] for level in LEVELS}
    # The order turns every round so that no level always runs first or
    # right after another (the disk's write-back of the last run's frames
    # and the machine's state drift would otherwise favour one position).
    for rep in range(a.reps):
        for i in range(len(LEVELS)):
            level = LEVELS[(rep + i) % len(LEVELS)]
            times[level].append(run(frameray, work, level, a.size))
    shutil.rmtree(work, ignore_errors=True)
    med = {l: (statistics.median(t[0] for t in times[l]), statistics.median(t[1] for t in times[l]))
           for l in LEVELS}
    lines = ["# Run log cost: float1 (51 frames, %s), %d runs each, alternating" % (
        a.size or "its INI's 320x240 +A0.2", a.reps),
             "", "Date: %s; cores: %d" % (datetime.date.today(), os.cpu_count()), "",
             "| Log_Level | median wall s | median CPU s | wall vs info | CPU vs info |"
             " median of per-round CPU ratios vs info |",
             "|---|---|---|---|---|---|"]
    for l in LEVELS:
        # Rounds pair the levels in time: the ratio within a round cancels
        # the machine's slow drift.
        paired = statistics.median(c[1] / i[1] for c, i in zip(times[l], times["info"]))
        lines.append("| %s | %.3f | %.3f | %+.1f %% | %+.1f %% | %+.1f %% |" % (
            l, med[l][0], med[l][1], 100 * (med[l][0] / med["info"][0] - 1),
            100 * (med[l][1] / med["info"][1] - 1), 100 * (paired - 1)))
    text = "\n".join(lines) + "\n"
    print(text)
    if a.out:
        with open(a.out, "w") as f:
            f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
