#!/usr/bin/env python3
"""Output safety: a frame that cannot be written ends the run cleanly.

    output_safety_test.py FRAMERAY WORKDIR

For each way writing can fail mid-sequence, frameray must exit with an
error status (1..127) and a message naming the frame file and the system's
reason; every file under a final frame name must be complete (listed in
the journal with its size), no temporary file may be left behind, and a
resumed run (+C) once the cause is gone must give frames byte-identical to
an uninterrupted run.

1. A full disk, simulated portably with a file-size limit (RLIMIT_FSIZE,
   as `ulimit -f` sets it, SIGXFSZ left at its default: frameray ignores
   the signal itself, so a write past the limit fails with EFBIG as a
   write to a full disk fails with ENOSPC, instead of killing it).
   Frames 1-3 fit under the limit and must be kept.
2. The output folder removed by a Pre_Frame_Command before a later frame.
3. The output folder made read-only before a later frame (only when not
   running as root: root writes anywhere).
"""
import os
import resource
import signal
import subprocess
import sys

from sequence_fixture import fail, make_sequence

SCENE = """#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <4, 6, -5> rgb 1 }
// Frames 1-3 compress to a few kB, later ones (fine noise) to far more:
// a file-size limit between the two fails the sequence at frame 4.
#if (frame_number <= 3)
  plane { y, 0 pigment { rgb <0.6, 0.7, 0.6> } }
#else
  plane { y, 0 pigment { bozo scale 0.01 } }
#end
sphere { <-2 + 4 * clock, 1, 0>, 0.8 pigment { rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
#debug concat("frame ", str(frame_number, 0, 0), "\\n")
"""

FRAMES = 8


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    frameray = os.path.abspath(sys.argv[1])
    work = os.path.abspath(sys.argv[2])
    ini, env = make_sequence(
        work, "ball", SCENE,
        "Width=160\nHeight=120\nInitial_Frame=1\nFinal_Frame=%d\n"
        "Display=off\nVerbose=off\n" % FRAMES)

    def run(outdir, extra, preexec=None):
        cmd = [frameray, ini, "+O%s/" % outdir] + extra
        r = subprocess.run(cmd, cwd=work, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           preexec_fn=preexec)
        return r, r.stdout.decode(errors="replace")

    ref = os.path.join(work, "ref")
    r, out = run(ref, [])
    if r.returncode != 0:
        fail("reference run exited %d:\n%s" % (r.returncode, out))
    frames = sorted(n for n in os.listdir(ref) if n.endswith(".png"))
    if len(frames) != FRAMES:
        fail("reference run wrote %d frames, expected %d" % (len(frames), FRAMES))
    reference = {n: open(os.path.join(ref, n), "rb").read() for n in frames}
    # Room for each of the first three frames, not for the fourth.
    small = max(len(reference[n]) for n in frames[:3])
    big = min(len(reference[n]) for n in frames[3:])
    if big < 2 * small:
        fail("the test scene's frames do not grow enough (%d vs %d bytes)" % (small, big))
    limit = (small + big) // 2

    def check_failed_run(name, outdir, r, out, reason):
        print("--- %s: exit %d\n%s" % (name, r.returncode, out))
        if not 0 < r.returncode < 128:
            fail("%s: exit status %d, expected an error status 1..127" % (name, r.returncode))
        if reason not in out or "error: frame" not in out:
            fail("%s: no 'error: frame N: ... %s' message" % (name, reason))
        if not os.path.isdir(outdir):
            return
        journal = {}
        jpath = os.path.join(outdir, ".ball.frameray-journal")
        if os.path.exists(jpath):
            # frame <number> <clock> <size> <hash> <inputs> <file name>
            for line in open(jpath).read().splitlines()[1:]:
                parts = line.split()
                if parts and parts[0] == "frame":
                    journal[parts[6]] = int(parts[3])
        for n in os.listdir(outdir):
            if n.endswith(".tmp"):
                fail("%s: temporary file %s left behind" % (name, n))
            if n.endswith(".png"):
                data = open(os.path.join(outdir, n), "rb").read()
                if data != reference[n] or journal.get(n) != len(data):
                    fail("%s: %s is under its final name but is not the complete, journalled frame" % (name, n))

    def check_resumed(name, outdir):
        r, out = run(outdir, ["+C"])
        if r.returncode != 0:
            fail("%s: resumed run exited %d:\n%s" % (name, r.returncode, out))
        for n in frames:
            if open(os.path.join(outdir, n), "rb").read() != reference[n]:
                fail("%s: resumed %s differs from the uninterrupted run" % (name, n))
        print("%s: resumed, %d frames byte-identical" % (name, FRAMES))

    # 1. Full disk (file-size limit).
    def limit_file_size():
        signal.signal(signal.SIGXFSZ, signal.SIG_DFL)
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))

    full = os.path.join(work, "full")
    os.makedirs(full)
    r, out = run(full, [], preexec=limit_file_size)
    check_failed_run("full disk", full, r, out, "File too large")
    if sorted(n for n in os.listdir(full) if n.endswith(".png")) != frames[:3]:
        fail("full disk: frames 1-3 (which fit) must be kept, and no later frame")
    check_resumed("full disk", full)

    # 2. The output folder vanishes before frame 4.
    gone = os.path.join(work, "gone")
    hook = "Pre_Frame_Command=sh -c 'test %%n -eq 4 && rm -rf %s; exit 0'" % gone
    r, out = run(gone, ["Allow_Shell_Commands=on", hook])
    check_failed_run("vanished folder", gone, r, out, "No such file or directory")
    check_resumed("vanished folder", gone)

    # 3. The output folder made read-only before frame 4 (as root every
    # folder stays writable: skipped then).
    if os.geteuid() != 0:
        locked = os.path.join(work, "locked")
        hook = "Pre_Frame_Command=sh -c 'test %%n -eq 4 && chmod 555 %s; exit 0'" % locked
        r, out = run(locked, ["Allow_Shell_Commands=on", hook])
        os.chmod(locked, 0o755)
        check_failed_run("read-only folder", locked, r, out, "Permission denied")
        check_resumed("read-only folder", locked)
    else:
        print("read-only folder: skipped (running as root)")
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
