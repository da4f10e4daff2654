#!/usr/bin/env python3
"""Stop-and-resume test of the frame loop (Continue_Trace, +C).

    resume_kill_test.py FRAMERAY WORKDIR [KILLS]

1. Renders a multi-frame animation uninterrupted (the reference).
2. Starts the same render with +C again and again and kills it with
   SIGKILL at KILLS (>= 20) random moments; then lets a final +C run finish.
   Every frame must equal the reference byte for byte, and no temporary
   file may be left behind.
3. Truncates a finished frame: a +C run must render it again (a file that
   does not match the journal is never trusted).
4. Sends SIGINT: the run must stop within 2 s with status 2, run
   User_Abort_Command, and a +C run must complete the sequence identically.
"""
import os
import random
import shutil
import signal
import subprocess
import sys

from sequence_fixture import fail, make_sequence
import time

SCENE = """#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <4, 6, -5> rgb 1 }
plane { y, 0 pigment { rgb <0.6, 0.7, 0.6> } }
sphere { <-2 + 4 * clock, 1, 0>, 0.8 pigment { rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
box { <-0.5, 0, 1>, <0.5, 1 + clock, 2> pigment { rgb <0.2, 0.4, 1> } }
#debug concat("frame ", str(frame_number, 0, 0), "\\n")
"""

FRAMES = 20


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    frameray = os.path.abspath(sys.argv[1])
    work = os.path.abspath(sys.argv[2])
    kills = int(sys.argv[3]) if len(sys.argv) > 3 else 24
    ini, env = make_sequence(
        work, "orbit", SCENE,
        "Width=320\nHeight=240\nInitial_Frame=1\nFinal_Frame=%d\n"
        "Verbose=off\nDebug_Console=off\n" % FRAMES)

    def run(outdir, extra, check=True):
        cmd = [frameray, ini, "+O%s/" % outdir] + extra
        r = subprocess.run(cmd, cwd=work, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        if check and r.returncode != 0:
            fail("%s exited %d:\n%s" % (" ".join(cmd), r.returncode, r.stdout.decode(errors="replace")))
        return r

    # Start-up (loading the shared libraries) takes a good part of a short
    # run; kills are spread over start-up and the rendering after it.
    t0 = time.monotonic()
    subprocess.run([frameray, "--help"], stdout=subprocess.DEVNULL, env=env)
    startup = time.monotonic() - t0
    ref = os.path.join(work, "ref")
    t0 = time.monotonic()
    run(ref, [])
    duration = time.monotonic() - t0
    names = sorted(n for n in os.listdir(ref) if n.endswith(".png"))
    if len(names) != FRAMES:
        fail("reference run wrote %d frames, expected %d" % (len(names), FRAMES))
    reference = {n: open(os.path.join(ref, n), "rb").read() for n in names}

    def compare(outdir, what):
        got = sorted(n for n in os.listdir(outdir) if n.endswith(".png"))
        if got != names:
            fail("%s: frames %s, expected %s" % (what, got, names))
        for n in names:
            if open(os.path.join(outdir, n), "rb").read() != reference[n]:
                fail("%s: %s differs from the uninterrupted run" % (what, n))
        leftovers = [n for n in os.listdir(outdir) if n.endswith(".tmp")]
        if leftovers:
            fail("%s: temporary files left: %s" % (what, leftovers))

    # 2. SIGKILL at random moments.
    rng = random.Random(20240607)
    test = os.path.join(work, "killed")
    os.makedirs(test)
    finished_early = restarts = 0
    for i in range(kills):
        done = len([n for n in os.listdir(test) if n.endswith(".png")])
        if done == FRAMES:
            # Everything is finished: start over so that the next kills land
            # in the middle of a sequence again.
            shutil.rmtree(test)
            os.makedirs(test)
            restarts += 1
            done = 0
        p = subprocess.Popen([frameray, ini, "+O%s/" % test, "+C"], cwd=work, env=env,
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        # A random moment within what is left of the run (start-up, parsing,
        # rendering, writing, journal).
        remaining = max(duration - startup, 0.05) * (FRAMES - done) / FRAMES
        time.sleep(rng.uniform(0.0, startup + remaining * 1.1) if i % 4 == 0 else
                   startup + rng.uniform(0.0, remaining * 1.1))
        if p.poll() is None:
            p.send_signal(signal.SIGKILL)
        else:
            finished_early += 1
        p.wait()
    run(test, ["+C"])
    compare(test, "after %d kills" % kills)
    print("ok: %d SIGKILLs (%d runs finished before the kill, %d restarts), sequence identical" %
          (kills, finished_early, restarts))

    # 3. A truncated frame is rendered again.
    victim = os.path.join(test, names[4])
    data = open(victim, "rb").read()
    with open(victim, "wb") as f:
        f.write(data[: len(data) // 2])
    mtimes = {n: os.stat(os.path.join(test, n)).st_mtime_ns for n in names}
    run(test, ["+C"])
    compare(test, "after truncating %s" % names[4])
    rerendered = [n for n in names if os.stat(os.path.join(test, n)).st_mtime_ns != mtimes[n]]
    if rerendered != [names[4]]:
        fail("+C re-rendered %s, expected only %s" % (rerendered, names[4]))
    print("ok: truncated %s rendered again, the other frames kept" % names[4])

    # 4. SIGINT stops within 2 s, runs User_Abort_Command, and resumes.
    flag = os.path.join(work, "aborted.flag")
    abort_ini = os.path.join(work, "abort.ini")
    with open(abort_ini, "w") as f:
        f.write("User_Abort_Command=touch %s\n" % flag)
    stopped = os.path.join(work, "stopped")
    os.makedirs(stopped)
    p = subprocess.Popen([frameray, ini, abort_ini, "Allow_Shell_Commands=on", "+O%s/" % stopped], cwd=work, env=env,
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    # Once frames are being written (the handler is installed in main).
    deadline = time.monotonic() + 60
    while len([n for n in os.listdir(stopped) if n.endswith(".png")]) < 2:
        if time.monotonic() > deadline or p.poll() is not None:
            fail("the SIGINT run did not start writing frames")
        time.sleep(0.01)
    sent = time.monotonic()
    p.send_signal(signal.SIGINT)
    try:
        _, err = p.communicate(timeout=10)
    except subprocess.TimeoutExpired:
        p.kill()
        fail("SIGINT did not stop the run within 10 s")
    took = time.monotonic() - sent
    if took > 2.0:
        fail("SIGINT took %.2f s to stop the run (limit 2 s)" % took)
    if p.returncode != 2:
        fail("SIGINT: exit status %d, expected 2; stderr:\n%s" % (p.returncode, err.decode(errors="replace")))
    if not os.path.exists(flag):
        fail("SIGINT: User_Abort_Command did not run")
    done = len([n for n in os.listdir(stopped) if n.endswith(".png")])
    run(stopped, ["+C"])
    compare(stopped, "after SIGINT and +C")
    print("ok: SIGINT stopped in %.2f s after %d of %d frames, User_Abort_Command ran, +C completed" %
          (took, done, FRAMES))
    return 0


if __name__ == "__main__":
    sys.exit(main())
