#!/usr/bin/env python3
"""Looking at a sequence: the contact sheet and the preview video (issue 29).

    looking_test.py FRAMERAY SCENE WORKDIR

1. 8 frames with Contact_Sheet=on Preview_Video=mp4: headless Chromium's
   screenshot of NAME.html shows 8 thumbnails (the scene's green sky, one
   band per 160-pixel-wide thumbnail); the player steps frames (`?step=3`
   shows frame 4, `?frame=6` frame 6, in the DOM Chromium dumps after the
   page's script ran); NAME-sheet.png is the 3 x 3 grid; ffprobe counts 8
   H.264 frames at 24 per second in NAME.mp4.
2. +C after frames 6-8 were deleted: the page lists frames 1-5 as kept
   (with thumbnails) and 6-8 as rendered; the video is made again.
3. A failing frame (5): the run fails, the page marks frame 5 failed and
   6-8 not rendered; no video (not every frame exists).
4. ffmpeg missing, or without the libx264 encoder: the run stops before
   any frame with an error naming what is missing.
5. Two shards, one after the other into one folder: each writes its own
   page; the first makes no video, the second (which completes the
   sequence) makes it with all 8 frames.
6. Preview_Video=webm Preview_Fps=12 at an odd size: 8 VP9 frames at 12/s.
"""
import os
import re
import shutil
import stat
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bench"))
from png_compare import read_png  # noqa: E402

FRAMES = 8


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def render(frameray, scene, out, *extra, expect=0, env=None):
    args = [frameray, scene, "+W64", "+H48", "+KFI1", "+KFF%d" % FRAMES, "+O" + out + "/",
            "+WT2"] + list(extra)
    r = subprocess.run(args, capture_output=True, text=True, env=env)
    if r.returncode != expect:
        fail("%s exited %d (expected %d):\n%s" % (" ".join(args), r.returncode, expect, r.stderr))
    return r


def chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        if shutil.which(name):
            return name
    fail("no chromium on PATH (Debian package chromium; scripts/setup.sh installs it)")


def browse(page, how, work):
    profile = tempfile.mkdtemp(dir=work)
    args = [chromium(), "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
            "--user-data-dir=" + profile, "--window-size=1000,1000"] + how + ["file://" + page]
    r = subprocess.run(args, capture_output=True, text=True, timeout=120)
    shutil.rmtree(profile, ignore_errors=True)
    if r.returncode != 0:
        fail("%s failed:\n%s" % (" ".join(args), r.stderr))
    return r.stdout


def green_bands(png):
    """Connected regions of the scene's green sky at least 150 pixels wide
    and at most 170 (one per 160-pixel thumbnail; the player's large view
    is 480 wide)."""
    image = read_png(png)
    w, h, n, s = image.width, image.height, image.channels, image.samples
    mask = bytearray(w * h)
    for i in range(w * h):
        r, g, b = s[i * n], s[i * n + 1], s[i * n + 2]
        mask[i] = 1 if g > 180 and r < 80 and b < 80 else 0
    widths = []
    for start in range(w * h):
        if not mask[start]:
            continue
        mask[start] = 0
        stack, x0, x1 = [start], w, -1
        while stack:
            i = stack.pop()
            x = i % w
            x0, x1 = min(x0, x), max(x1, x)
            for j in (i - 1 if x > 0 else -1, i + 1 if x + 1 < w else -1, i - w, i + w):
                if 0 <= j < w * h and mask[j]:
                    mask[j] = 0
                    stack.append(j)
        widths.append(x1 - x0 + 1)
    return [x for x in widths if 150 <= x <= 170], widths


def probe(video):
    r = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
                        "-show_entries", "stream=codec_name,nb_read_frames,r_frame_rate",
                        "-of", "default=nw=1", video], capture_output=True, text=True)
    if r.returncode != 0:
        fail("ffprobe %s: %s" % (video, r.stderr))
    return dict(line.split("=", 1) for line in r.stdout.split())


def cells(page):
    text = open(page).read()
    return re.findall(r'<div class="cell (\w+)" data-index="\d+" data-frame="(\d+)"', text)


def current_frame(page, query, work):
    dom = browse(page + query, ["--dump-dom"], work)
    m = re.search(r'<span id="current" data-frame="(\d+)">', dom)
    if not m:
        fail("no current frame in the DOM for %s" % query)
    return int(m.group(1))


def check_full_run(frameray, scene, work):
    out = os.path.join(work, "full")
    render(frameray, scene, out, "Contact_Sheet=on", "Preview_Video=mp4")
    page = os.path.join(out, "spin.html")
    shot = os.path.join(work, "page.png")
    browse(page, ["--screenshot=" + shot], work)
    bands, widths = green_bands(shot)
    if len(bands) != FRAMES:
        fail("the screenshot shows %d thumbnails, expected %d (green regions %s)"
             % (len(bands), FRAMES, widths))
    for query, want in (("?step=3", 4), ("?frame=6", 6), ("?step=9", 2)):
        got = current_frame(page, query, work)
        if got != want:
            fail("the player shows frame %d for '%s', expected %d" % (got, query, want))
    grid = read_png(os.path.join(out, "spin-sheet.png"))
    if (grid.width, grid.height) != (3 * 68 + 4, 3 * 52 + 4):
        fail("the grid image is %dx%d" % (grid.width, grid.height))
    info = probe(os.path.join(out, "spin.mp4"))
    if info != {"codec_name": "h264", "r_frame_rate": "24/1", "nb_read_frames": str(FRAMES)}:
        fail("spin.mp4: %s" % info)
    return out


def check_resume(frameray, scene, out):
    for n in (6, 7, 8):
        os.remove(os.path.join(out, "spin%d.png" % n))
    os.remove(os.path.join(out, "spin.mp4"))
    render(frameray, scene, out, "Contact_Sheet=on", "Preview_Video=mp4", "+C")
    got = cells(os.path.join(out, "spin.html"))
    want = [("kept", str(n)) for n in range(1, 6)] + [("rendered", str(n)) for n in (6, 7, 8)]
    if got != want:
        fail("after +C the page lists %s" % got)
    if open(os.path.join(out, "spin.html")).read().count("data:image/png;base64,") != FRAMES:
        fail("after +C not every frame has its thumbnail")
    if probe(os.path.join(out, "spin.mp4"))["nb_read_frames"] != str(FRAMES):
        fail("the video after +C")


def check_failure(frameray, scene, work):
    out = os.path.join(work, "failed")
    render(frameray, scene, out, "Contact_Sheet=on", "Preview_Video=mp4", "Declare=FailAt=5",
           "+WF1", expect=1)
    got = cells(os.path.join(out, "spin.html"))
    want = [("rendered", str(n)) for n in range(1, 5)] + [("failed", "5")] + \
        [("pending", str(n)) for n in (6, 7, 8)]
    if got != want:
        fail("with frame 5 failing the page lists %s" % got)
    if "frame failed on purpose" not in open(os.path.join(out, "spin.html")).read():
        fail("the failed frame's message is not on the page")
    if os.path.exists(os.path.join(out, "spin.mp4")):
        fail("a video was made although frames are missing")


def check_missing_encoder(frameray, scene, work):
    fake = os.path.join(work, "fakebin")
    os.makedirs(fake)
    script = os.path.join(fake, "ffmpeg")
    with open(script, "w") as f:
        f.write("#!/bin/sh\necho ' V....D libvpx-vp9           libvpx VP9'\n")
    os.chmod(script, stat.S_IRWXU)
    for path, words in ((fake, "libx264"), (os.path.join(work, "nowhere"), "ffmpeg program")):
        out = os.path.join(work, "noencoder")
        env = dict(os.environ, PATH=path)
        r = render(frameray, scene, out, "Preview_Video=mp4", expect=2, env=env)
        if words not in r.stderr:
            fail("a missing %s is not named: %s" % (words, r.stderr))
        if os.path.exists(out):
            fail("frames were rendered although the video cannot be made")


def check_shards(frameray, scene, work):
    out = os.path.join(work, "shards")
    r = render(frameray, scene, out, "Contact_Sheet=on", "Preview_Video=mp4", "+SHI0", "+SHC2")
    if os.path.exists(os.path.join(out, "spin.mp4")):
        fail("the first shard made a video")
    if "4 of 8 frames exist" not in r.stderr:
        fail("the first shard does not say why there is no video: " + r.stderr)
    render(frameray, scene, out, "Contact_Sheet=on", "Preview_Video=mp4", "+SHI1", "+SHC2")
    for shard, numbers in ((0, (1, 3, 5, 7)), (1, (2, 4, 6, 8))):
        got = cells(os.path.join(out, "spin.shard-%d-of-2.html" % shard))
        if got != [("rendered", str(n)) for n in numbers]:
            fail("shard %d's page lists %s" % (shard, got))
    if probe(os.path.join(out, "spin.mp4"))["nb_read_frames"] != str(FRAMES):
        fail("the shards' video")


def check_webm(frameray, scene, work):
    out = os.path.join(work, "webm")
    args = [frameray, scene, "+W65", "+H49", "+KFI1", "+KFF%d" % FRAMES, "+O" + out + "/",
            "Preview_Video=webm", "Preview_Fps=12", "-V"]
    r = subprocess.run(args, capture_output=True, text=True)
    if r.returncode != 0:
        fail("webm: " + r.stderr)
    info = probe(os.path.join(out, "spin.webm"))
    if info != {"codec_name": "vp9", "r_frame_rate": "12/1", "nb_read_frames": str(FRAMES)}:
        fail("spin.webm: %s" % info)


def main():
    frameray, scene, work = sys.argv[1], os.path.abspath(sys.argv[2]), os.path.abspath(sys.argv[3])
    for tool in ("ffprobe", "ffmpeg"):
        if not shutil.which(tool):
            fail("%s is missing (Debian package ffmpeg; scripts/setup.sh installs it)" % tool)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    out = check_full_run(frameray, scene, work)
    check_resume(frameray, scene, out)
    check_failure(frameray, scene, work)
    check_missing_encoder(frameray, scene, work)
    check_shards(frameray, scene, work)
    check_webm(frameray, scene, work)
    print("looking_test: OK")


main()
