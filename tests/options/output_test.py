#!/usr/bin/env python3
"""+O-, Grayscale_Output and Include_Header as povray 3.7 does them (issue 30).

Measured with povray 3.7.0.10: `+O-` writes the image to standard output,
PNG by default, PPM with +FP, the frames of an animation one after another
(three 16x12 frames: three PNG files back to back), messages on standard
error. Grayscale_Output writes a one-channel 16-bit PNG (also at the
default 8 bits) and a P5 PPM whose grey is 0.297 R' + 0.589 G' + 0.114 B'
of the colour file values.

    output_test.py FRAMERAY SCRATCH
"""
import os
import shutil
import struct
import subprocess
import sys
import zlib

SCENE = """#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -4> look_at 0 }
light_source { <5, 8, -6> rgb 1 }
sphere { 0, 1 pigment { gradient x color_map { [0 rgb <1, 0.2, 0.1>] [1 rgb <0.1, 0.3, 1>] } }
         translate x * clock }
plane { y, -1 pigment { checker rgb 0.2 rgb 0.9 } }
"""


def run(frameray, cwd, args):
    env = {k: v for k, v in os.environ.items() if k not in ("POVINI", "POVRAYOPT", "XDG_CONFIG_HOME")}
    env["HOME"] = os.path.join(cwd, "home")
    p = subprocess.run([frameray, "scene.pov", "+W16", "+H12"] + args, cwd=cwd, env=env,
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    if p.returncode != 0:
        sys.exit(f"frameray {' '.join(args)} failed ({p.returncode}): {p.stderr.decode()}")
    return p.stdout, p.stderr.decode()


def read(path):
    with open(path, "rb") as f:
        return f.read()


def png_chunks(data):
    i = 8
    while i < len(data):
        (n,) = struct.unpack(">I", data[i:i + 4])
        yield data[i + 4:i + 8], data[i + 8:i + 8 + n]
        i += 12 + n


def png_samples(data):
    """(bit depth, colour type, channels, samples row-major) of a PNG."""
    idat = b""
    for kind, body in png_chunks(data):
        if kind == b"IHDR":
            w, h, depth, ctype = struct.unpack(">IIBB", body[:10])
        elif kind == b"IDAT":
            idat += body
    raw = zlib.decompress(idat)
    ch = {0: 1, 2: 3, 4: 2, 6: 4}[ctype]
    bpp = ch * depth // 8
    stride = w * bpp
    prev = bytearray(stride)
    out = []
    i = 0
    for _ in range(h):
        f = raw[i]
        line = bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if f == 1:
                line[x] = (line[x] + a) & 255
            elif f == 2:
                line[x] = (line[x] + b) & 255
            elif f == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        out += struct.unpack(">%dH" % (stride // 2), line) if depth == 16 else list(line)
        prev = line
    return depth, ctype, ch, out


def ppm_parts(data):
    """(magic, width, height, maxval, pixel bytes, rest) of the first PPM in data."""
    toks, i = [], 0
    while len(toks) < 4:
        while data[i:i + 1].isspace():
            i += 1
        if data[i:i + 1] == b"#":
            while data[i:i + 1] != b"\n":
                i += 1
            continue
        j = i
        while not data[j:j + 1].isspace():
            j += 1
        toks.append(data[i:j])
        i = j
    i += 1
    w, h, maxval = int(toks[1]), int(toks[2]), int(toks[3])
    ch = 3 if toks[0] == b"P6" else 1
    size = w * h * ch * (2 if maxval > 255 else 1)
    return toks[0], w, h, maxval, data[i:i + size], data[i + size:]


def report(name, failures):
    """Prints the failures and the verdict; the exit status."""
    for f in failures:
        print("FAIL:", f)
    print(f"{name}:", "ok" if not failures else f"{len(failures)} failures")
    return 1 if failures else 0


def main():
    frameray, scratch = sys.argv[1], sys.argv[2]
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(os.path.join(scratch, "home"))
    with open(os.path.join(scratch, "scene.pov"), "w") as f:
        f.write(SCENE)
    failures = []

    # A still and an animation to standard output equal the files; +O-
    # writes no file (no journal, frame log or sequence.json either).
    streams = {}
    for kind, args in (("png", []), ("ppm", ["+FP"])):
        streams[kind] = (run(frameray, scratch, args + ["+O-"]),
                         run(frameray, scratch, args + ["+O-", "+KFF3"]))
    leftovers = sorted(set(os.listdir(scratch)) - {"home", "scene.pov"})
    if leftovers:
        failures.append(f"+O- left files behind: {leftovers}")
    for kind, args in (("png", []), ("ppm", ["+FP"])):
        ext = "." + kind
        (still, _), (stream, err) = streams[kind]
        run(frameray, scratch, args + ["+Ostill" + ext])
        if still != read(os.path.join(scratch, "still" + ext)):
            failures.append(f"{kind} still on standard output differs from the file")
        run(frameray, scratch, args + ["+Oframes/", "+KFF3"])
        frames = b"".join(read(os.path.join(scratch, "frames", f"scene{n}{ext}")) for n in (1, 2, 3))
        if stream != frames:
            failures.append(f"{kind} stream of 3 frames differs from the 3 files back to back")
        if "standard output" not in err:
            failures.append(f"{kind}: no frame messages on standard error: {err!r}")

    # Grayscale_Output: PNG one 16-bit grey channel, PPM a P5; both the
    # grey of the colour file values.
    run(frameray, scratch, ["+FN16", "+Ocolour.png"])
    run(frameray, scratch, ["Grayscale_Output=on", "+Ogrey.png"])
    run(frameray, scratch, ["Grayscale_Output=on", "+FP", "+Ogrey.ppm"])
    run(frameray, scratch, ["+FP", "+Ocolour.ppm"])
    depth, ctype, ch, colour = png_samples(read(os.path.join(scratch, "colour.png")))
    gdepth, gtype, gch, grey = png_samples(read(os.path.join(scratch, "grey.png")))
    if (gdepth, gtype) != (16, 0):
        failures.append(f"grey PNG is depth {gdepth}, colour type {gtype}; povray: 16, 0")
    else:
        worst = max(abs(0.297 * colour[3 * i] + 0.589 * colour[3 * i + 1] + 0.114 * colour[3 * i + 2]
                        - grey[i]) for i in range(len(grey)))
        if worst > 1.5:
            failures.append(f"grey PNG differs from the grey of the colour by {worst} levels")
    magic, w, h, maxval, px, _ = ppm_parts(read(os.path.join(scratch, "grey.ppm")))
    _, _, _, _, cpx, _ = ppm_parts(read(os.path.join(scratch, "colour.ppm")))
    if (magic, maxval, len(px)) != (b"P5", 255, 16 * 12):
        failures.append(f"grey PPM is {magic} maxval {maxval} with {len(px)} bytes")
    else:
        worst = max(abs(0.297 * cpx[3 * i] + 0.589 * cpx[3 * i + 1] + 0.114 * cpx[3 * i + 2] - px[i])
                    for i in range(len(px)))
        if worst > 1.5:
            failures.append(f"grey PPM differs from the grey of the colour by {worst} levels")

    # Include_Header (+HI): read before the scene, found through the
    # library path. povray 3.7.0.10 writes this scene's 4x4 PPM as
    # 255 188 0 and stops with "Cannot open include header file" when the
    # header is missing.
    os.makedirs(os.path.join(scratch, "lib"))
    with open(os.path.join(scratch, "lib", "head.inc"), "w") as f:
        f.write("#declare HC = rgb <1, 0.5, 0>;\n")
    with open(os.path.join(scratch, "header.pov"), "w") as f:
        f.write("#version 3.7;\nglobal_settings { assumed_gamma 1 }\nbackground { HC }\n")
    env = {k: v for k, v in os.environ.items() if k not in ("POVINI", "POVRAYOPT", "XDG_CONFIG_HOME")}
    env["HOME"] = os.path.join(scratch, "home")
    p = subprocess.run([frameray, "header.pov", "+W4", "+H4", "+FP", "+Oheader.ppm", "+HIhead.inc",
                        "+Llib"], cwd=scratch, env=env, capture_output=True)
    if p.returncode != 0:
        failures.append(f"Include_Header: exit {p.returncode}: {p.stderr.decode()}")
    else:
        _, _, _, _, px, _ = ppm_parts(read(os.path.join(scratch, "header.ppm")))
        if list(px[:3]) != [255, 188, 0]:
            failures.append(f"Include_Header: pixel {list(px[:3])}, povray 255 188 0")
    p = subprocess.run([frameray, "header.pov", "+W4", "+H4", "+Omissing.png", "+HInope.inc"],
                       cwd=scratch, env=env, capture_output=True)
    if p.returncode == 0 or b"cannot open include header file 'nope.inc'" not in p.stderr:
        failures.append(f"Include_Header missing: exit {p.returncode}: {p.stderr.decode()}")

    # Real_Time_Raytracing (+RTR): povray 3.7.0.10 without a display renders
    # every frame once, writes no image and warns of a beta feature.
    rtr = os.path.join(scratch, "rtr")
    os.makedirs(rtr)
    p = subprocess.run([frameray, os.path.join(scratch, "header.pov"), "+W4", "+H4", "+KFI1",
                        "+KFF3", "+RTR", "+HIhead.inc", "+L" + os.path.join(scratch, "lib"),
                        "+O" + rtr + "/"], cwd=scratch, env=env, capture_output=True)
    if p.returncode != 0 or os.listdir(rtr) or b"Real_Time_Raytracing" not in p.stderr:
        failures.append(f"+RTR: exit {p.returncode}, files {os.listdir(rtr)}: {p.stderr.decode()}")

    # Dither_Method=FS as povray 3.7.0.10 writes it, and Declare= values
    # kept to six significant digits as povray keeps them: a flat field of
    # Declare=V=100.5/255 (read as 0.394118) at File_Gamma 1.0. povray's
    # 16x16 PPM: rows "1010..." twice, then "0101..." twice (levels minus
    # 100), the pattern column 0's delayed error gives; plain
    # Floyd-Steinberg or the unrounded value give other pixels.
    with open(os.path.join(scratch, "flat.pov"), "w") as f:
        f.write("#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
                "camera { orthographic location <0,0,-1> look_at 0 right x up y }\n"
                "plane { z, 0 pigment { rgb V } finish { emission 1 diffuse 0 ambient 0 } }\n")
    p = subprocess.run([frameray, "flat.pov", "+W16", "+H16", "-A", "+FP", "+Oflat.ppm",
                        "File_Gamma=1.0", "Dither=on", "Dither_Method=FS",
                        "Declare=V=0.3941176470588235"], cwd=scratch, env=env, capture_output=True)
    if p.returncode != 0:
        failures.append(f"FS dither: exit {p.returncode}: {p.stderr.decode()}")
    else:
        _, _, _, _, px, _ = ppm_parts(read(os.path.join(scratch, "flat.ppm")))
        got = ["".join(str(px[3 * (16 * y + x)] - 100) for x in range(16)) for y in range(16)]
        want = ["10" * 8 if y % 4 < 2 else "01" * 8 for y in range(16)]
        if got != want:
            failures.append(f"FS dither: rows {got}, povray {want}")

    return report("output_test", failures)


if __name__ == "__main__":
    sys.exit(main())
