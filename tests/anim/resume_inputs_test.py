#!/usr/bin/env python3
"""Resume (+C) re-renders exactly the frames whose inputs changed.

    resume_inputs_test.py FRAMERAY WORKDIR

The journal records what each frame was made from: the files its parse read
(scene, includes, image maps, #read data) with their content hashes, and
the options. A run with +C keeps a frame only when its image and all of
those are unchanged:

1. Nothing changed: every frame is kept.
2. An include read only by frame 3 is edited: frame 3 alone is rendered.
3. An image map every frame uses is replaced: every frame is rendered.
4. A data file read with #fopen by frames 2 and 4 is edited: those two.
5. The scene is edited: every frame.
6. An option that changes the images (+A): every frame; one that does not
   (+WT1): none.
7. A state file one frame writes and the next reads (#write/#read) is not
   an input: resuming keeps the frames.
8. Two shards render the sequence; a plain +C afterwards sees their
   journals and keeps every frame.
"""
import os
import shutil
import subprocess
import sys

from sequence_fixture import fail

FRAMES = 4

SCENE = """#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -4> look_at 0 }
light_source { <3, 5, -4> rgb 1 }
#declare Shade = 0.5;
#if (frame_number = 3) #include "part.inc" #end
#if (mod(frame_number, 2) = 0)
  #fopen D "data.txt" read #read (D, Extra) #fclose D
#else
  #declare Extra = 0;
#end
#declare UseState = 1;
#if (UseState & frame_number = 1)
  #fopen S "state.txt" write #write (S, "1,") #fclose S
#elseif (UseState)
  #fopen S "state.txt" read #read (S, Previous) #fclose S
  #fopen S "state.txt" write #write (S, str(Previous + 1, 0, 0), ",") #fclose S
#end
plane { y, -1 pigment { image_map { png "tex.png" } rotate x * 90 scale 4 } }
sphere { <clock * 2 - 1, 0, 0>, 0.6 + Extra pigment { rgb Shade } }
"""


def write(path, text, mode="w"):
    with open(path, mode) as f:
        f.write(text)


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    frameray, work = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    write(os.path.join(work, "scene.pov"), SCENE)
    write(os.path.join(work, "part.inc"), "#declare Shade = 0.8;\n")
    write(os.path.join(work, "data.txt"), "0.1\n")

    def run(*extra, resume=True, expect_ok=True):
        args = [frameray, "scene.pov", "+W32", "+H24", f"+KFF{FRAMES}", "-GS", "+Oframes/"]
        args += (["+C"] if resume else []) + list(extra)
        proc = subprocess.run(args, cwd=work, capture_output=True, text=True, timeout=240)
        out = proc.stdout + proc.stderr
        if expect_ok and proc.returncode != 0:
            fail(f"{' '.join(args[1:])}: exit {proc.returncode}\n{out}")
        kept = {int(line.split()[1]) for line in out.splitlines()
                if line.startswith("frame ") and "finished already" in line}
        return kept, out

    # An image map, written by frameray itself.
    tex_scene = os.path.join(work, "tex.pov")
    write(tex_scene, "#version 3.7;\nbackground { rgb <0.2, 0.5, 0.9> }\n")
    subprocess.run([frameray, "tex.pov", "+W8", "+H8", "-GR", "-GS", "+Otex.png"], cwd=work,
                   check=True, capture_output=True)

    all_frames = set(range(1, FRAMES + 1))

    def expect(label, rendered, *extra):
        kept, out = run(*extra)
        if kept != all_frames - set(rendered):
            fail(f"{label}: rendered {sorted(all_frames - kept)}, expected {sorted(rendered)}\n{out}")
        print(f"{label}: rendered {sorted(rendered)}")

    run(resume=False)
    expect("nothing changed", [])
    write(os.path.join(work, "part.inc"), "#declare Shade = 0.3;\n")
    expect("include of frame 3 edited", [3])
    write(tex_scene, "#version 3.7;\nbackground { rgb <0.9, 0.5, 0.2> }\n")
    subprocess.run([frameray, "tex.pov", "+W8", "+H8", "-GR", "-GS", "+Otex.png"], cwd=work,
                   check=True, capture_output=True)
    expect("image map replaced", all_frames)
    write(os.path.join(work, "data.txt"), "0.2\n")
    expect("data of frames 2 and 4 edited", [2, 4])
    write(os.path.join(work, "scene.pov"), SCENE + "// edited\n")
    expect("scene edited", all_frames)
    expect("anti-aliasing on", all_frames, "+A0.1")
    expect("same options again", [], "+A0.1")
    expect("thread count", [], "+A0.1", "+WT1")
    # The state file changed with every frame; it is not an input.
    expect("state file", [], "+A0.1")

    # Shards, then one plain resume (a scene passing state through files
    # cannot be sharded: this one without its state file).
    write(os.path.join(work, "scene.pov"), SCENE.replace("UseState = 1", "UseState = 0"))
    shutil.rmtree(os.path.join(work, "frames"))
    for i in range(2):
        run(f"+SHI{i}", "+SHC2", resume=False)
    names = sorted(n for n in os.listdir(os.path.join(work, "frames")) if n.endswith(".png"))
    if len(names) != FRAMES:
        fail(f"the shards wrote {names}")
    expect("plain +C after shards", [])
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
