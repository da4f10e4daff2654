"""The conformance tests' image comparison, in Python, standard library only.

Same metric as tests/conformance/compare_images.cpp (frameray-compare): a
pixel matches when each of R, G, B (and A when both images have it) is within
`tolerance` (default 4) of the reference on a 0..255 scale; PSNR and RMSE are
over R, G, B. frameray-compare costs about a second per call (image library
start-up), far too slow for the thousand frames of the scoreboard, hence
this reader. It decodes the PNGs both renderers write (8 or 16 bits, grey,
grey+alpha, RGB, RGBA, no interlace) and plain PPM (P6); for anything else
it raises UnsupportedImage and callers fall back to frameray-compare.
"""

import math
import struct
import zlib
from dataclasses import dataclass

try:  # optional: only speeds the comparison up
    import numpy
except ImportError:
    numpy = None

# As in compare_images.cpp: an exact 4/255 difference counts as matching.
TOLERANCE_SLACK = 1e-3


class UnsupportedImage(Exception):
    pass


@dataclass
class Image:
    width: int
    height: int
    channels: int  # 3 or 4
    samples: list  # 0..255 scale, row-major, interleaved


@dataclass
class Comparison:
    match: float  # fraction of pixels within tolerance
    psnr_db: float  # over R, G, B; inf when identical
    rmse: float  # over R, G, B, 0..255 scale
    max_abs_diff: float


def _unfilter(raw, width, height, bpp):
    """Undoes the per-row PNG filters; bpp = bytes per complete pixel."""
    stride = width * bpp
    out = bytearray(stride * height)
    previous = bytearray(stride)
    pos = 0
    for y in range(height):
        kind = raw[pos]
        line = bytearray(raw[pos + 1:pos + 1 + stride])
        pos += 1 + stride
        if kind == 1:  # Sub
            for i in range(bpp, stride):
                line[i] = (line[i] + line[i - bpp]) & 0xFF
        elif kind == 2:  # Up
            line = bytearray((a + b) & 0xFF for a, b in zip(line, previous))
        elif kind == 3:  # Average
            for i in range(stride):
                left = line[i - bpp] if i >= bpp else 0
                line[i] = (line[i] + ((left + previous[i]) >> 1)) & 0xFF
        elif kind == 4:  # Paeth
            for i in range(stride):
                a = line[i - bpp] if i >= bpp else 0
                b = previous[i]
                c = previous[i - bpp] if i >= bpp else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                if pa <= pb and pa <= pc:
                    pred = a
                elif pb <= pc:
                    pred = b
                else:
                    pred = c
                line[i] = (line[i] + pred) & 0xFF
        elif kind != 0:
            raise UnsupportedImage(f"bad PNG filter {kind}")
        out[y * stride:(y + 1) * stride] = line
        previous = line
    return out


def _to_rgb(values, width, height, file_channels):
    """Widens grey to RGB, keeps alpha; values are 0..255 floats or ints."""
    if file_channels in (3, 4):
        return Image(width, height, file_channels, list(values))
    alpha = file_channels == 2
    samples = []
    for i in range(0, len(values), file_channels):
        g = values[i]
        samples += (g, g, g)
        if alpha:
            samples.append(values[i + 1])
    return Image(width, height, 4 if alpha else 3, samples)


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise UnsupportedImage(f"{path}: not a PNG")
    pos = 8
    idat = []
    header = None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
    if header is None:
        raise UnsupportedImage(f"{path}: no IHDR")
    width, height, depth, color, _, _, interlace = header
    channels = {0: 1, 2: 3, 4: 2, 6: 4}.get(color)
    if channels is None or depth not in (8, 16) or interlace:
        raise UnsupportedImage(f"{path}: PNG colour type {color}, depth {depth}, "
                               f"interlace {interlace}")
    bpp = channels * depth // 8
    raw = _unfilter(zlib.decompress(b"".join(idat)), width, height, bpp)
    if depth == 8:
        values = raw
    else:
        words = struct.unpack(f">{len(raw) // 2}H", raw)
        values = [w / 257.0 for w in words]
    return _to_rgb(values, width, height, channels)


def read_ppm(path):
    data = open(path, "rb").read()
    fields = []
    pos = 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(data[start:pos])
    if fields[0] != b"P6":
        raise UnsupportedImage(f"{path}: PPM {fields[0]!r}")
    width, height, maxval = int(fields[1]), int(fields[2]), int(fields[3])
    body = data[pos + 1:]
    if maxval < 256:
        values = [v * 255.0 / maxval for v in body[:width * height * 3]] if maxval != 255 \
            else body[:width * height * 3]
    else:
        words = struct.unpack(f">{width * height * 3}H", body[:width * height * 6])
        values = [w * 255.0 / maxval for w in words]
    return _to_rgb(values, width, height, 3)


def read_image(path):
    path = str(path)
    if path.lower().endswith(".png"):
        return read_png(path)
    if path.lower().endswith(".ppm"):
        return read_ppm(path)
    raise UnsupportedImage(f"{path}: not PNG or PPM")


def _compare_numpy(test, reference, channels, limit):
    t = numpy.asarray(test.samples, dtype=numpy.float64).reshape(-1, test.channels)
    r = numpy.asarray(reference.samples, dtype=numpy.float64).reshape(-1, reference.channels)
    diff = numpy.abs(t[:, :channels] - r[:, :channels])
    pixels = diff.shape[0]
    matching = int(numpy.count_nonzero((diff <= limit).all(axis=1)))
    mse = float((diff[:, :3] ** 2).mean()) if pixels else 0.0
    psnr = math.inf if mse == 0 else 10.0 * math.log10(255.0 * 255.0 / mse)
    worst = float(diff.max()) if pixels else 0.0
    return Comparison(matching / pixels if pixels else 1.0, psnr, math.sqrt(mse), worst)


def compare(test, reference, tolerance=4.0):
    """Compares two Images (see the module comment for the metric)."""
    if (test.width, test.height) != (reference.width, reference.height):
        raise UnsupportedImage(f"size {test.width}x{test.height} vs "
                               f"{reference.width}x{reference.height}")
    if numpy is not None:
        channels = 4 if test.channels == 4 and reference.channels == 4 else 3
        return _compare_numpy(test, reference, channels, tolerance + TOLERANCE_SLACK)
    channels = 4 if test.channels == 4 and reference.channels == 4 else 3
    limit = tolerance + TOLERANCE_SLACK
    ts, rs = test.samples, reference.samples
    tc, rc = test.channels, reference.channels
    pixels = test.width * test.height
    matching = 0
    squared = 0.0
    worst = 0.0
    for p in range(pixels):
        ti, ri = p * tc, p * rc
        ok = True
        for c in range(channels):
            d = abs(ts[ti + c] - rs[ri + c])
            if c < 3:
                squared += d * d
            if d > worst:
                worst = d
            if d > limit:
                ok = False
        if ok:
            matching += 1
    mse = squared / (3 * pixels) if pixels else 0.0
    psnr = math.inf if mse == 0 else 10.0 * math.log10(255.0 * 255.0 / mse)
    return Comparison(matching / pixels if pixels else 1.0, psnr, math.sqrt(mse), worst)


def compare_files(test_path, reference_path, tolerance=4.0):
    return compare(read_image(test_path), read_image(reference_path), tolerance)
