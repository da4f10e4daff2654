#!/usr/bin/env python3
# Writes the small source images of the image_* conformance scenes (pure
# Python, no libraries): run from this folder, commit the results.
import math
import struct
import zlib


def chunk(kind, data):
    c = struct.pack('>I', len(data)) + kind + data
    return c + struct.pack('>I', zlib.crc32(kind + data) & 0xffffffff)


def write_png(path, w, h, values, channels, extra=()):
    """values: flat 8-bit channel values, rows from the top; extra: chunks
    between IHDR and IDAT."""
    ctype = {1: 0, 2: 4, 3: 2, 4: 6}[channels]
    raw = b''.join(b'\0' + bytes(values[y * w * channels:(y + 1) * w * channels])
                   for y in range(h))
    data = b'\x89PNG\r\n\x1a\n'
    data += chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, ctype, 0, 0, 0))
    data += b''.join(extra)
    data += chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b'')
    open(path, 'wb').write(data)


def write_png_palette(path, w, h, indices, palette):
    """8-bit colour type 3 (palette) PNG."""
    raw = b''.join(b'\0' + bytes(indices[y * w:(y + 1) * w]) for y in range(h))
    data = b'\x89PNG\r\n\x1a\n'
    data += chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 3, 0, 0, 0))
    data += chunk(b'PLTE', bytes(v for p in palette for v in p))
    data += chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b'')
    open(path, 'wb').write(data)


def write_ppm(path, w, h, values):
    open(path, 'wb').write(b'P6\n%d %d\n255\n' % (w, h) + bytes(values))


def write_gif(path, w, h, indices, palette):
    """LZW with 9-bit codes and a clear code every 254 pixels."""
    pal = list(palette) + [(0, 0, 0)] * (256 - len(palette))
    out = b'GIF89a' + struct.pack('<HHBBB', w, h, 0xF7, 0, 0)
    out += bytes(v for p in pal for v in p)
    out += b',' + struct.pack('<HHHHB', 0, 0, w, h, 0)
    codes = []
    for i, v in enumerate(indices):
        if i % 254 == 0:
            codes.append(256)
        codes.append(v)
    codes.append(257)
    bits = nbits = 0
    packed = bytearray()
    for c in codes:
        bits |= c << nbits
        nbits += 9
        while nbits >= 8:
            packed.append(bits & 255)
            bits >>= 8
            nbits -= 8
    if nbits:
        packed.append(bits & 255)
    out += bytes([8])
    for i in range(0, len(packed), 255):
        block = packed[i:i + 255]
        out += bytes([len(block)]) + bytes(block)
    open(path, 'wb').write(out + b'\0;')


# 16 x 8 colour grid: red across, green down, a blue checker, a white
# border column and row so orientation is visible.
grid = []
for y in range(8):
    for x in range(16):
        if x == 0 or y == 0:
            grid += [255, 255, 255]
        else:
            grid += [x * 16 + 8, 255 - y * 32, 200 if (x + y) % 2 else 40]
write_png('image_grid.png', 16, 8, grid, 3)
write_ppm('image_grid.ppm', 16, 8, grid)

# 8 x 8 RGBA: colour bands with alpha falling from left to right.
rgba = []
for y in range(8):
    for x in range(8):
        rgba += [255 - y * 30, 60 + y * 20, 40 + x * 25, 255 - x * 36]
write_png('image_alpha.png', 8, 8, rgba, 4)

# 8 x 8 palette image: four colours in a ring pattern.
palette = [(230, 40, 40), (40, 200, 60), (40, 60, 220), (240, 220, 40), (250, 250, 250)]
idx = []
for y in range(8):
    for x in range(8):
        r = max(abs(x - 3.5), abs(y - 3.5))
        idx.append(int(r) % 5)
write_gif('image_palette.gif', 8, 8, idx, palette)

# 32 x 32 grey heights: a dome and a ridge.
heights = []
for y in range(32):
    for x in range(32):
        d = math.hypot(x - 10.5, y - 12.5) / 9.0
        v = max(0.0, 1.0 - d * d) * 200
        if 22 <= x <= 25:
            v = 255
        heights.append(int(v))
write_png('image_heights.png', 32, 32, heights, 1)

# 32 x 32 palette heights for mesh_hf_gif.pov: a dome of indices 0..250
# with a ridge; the palette's colours are unrelated to the index (povray
# takes the index as the height).
hf_palette = [((i * 97) % 256, (i * 57) % 256, (i * 31) % 256) for i in range(256)]
hf_idx = []
for y in range(32):
    for x in range(32):
        d = math.hypot(x - 15.5, y - 15.5) / 22.0
        v = max(0.0, 1.0 - d * d) * 200 + (50 if abs(x - y) < 2 else 0)
        hf_idx.append(min(250, int(v)))
write_gif('mesh_hf_heights.gif', 32, 32, hf_idx, hf_palette)

# A 32 x 32 Fractint continuous-potential (pot) file for mesh_hf_pot.pov:
# a GIF 64 wide whose row halves hold the 16-bit heights' high bytes (left)
# and low bytes (right): a smooth dome with fine ripples only the low byte
# resolves.
pot_idx = []
for y in range(32):
    row = []
    for x in range(32):
        d = math.hypot(x - 14.5, y - 16.5) / 20.0
        v = max(0.0, 1.0 - d * d) * 50000 + 600 * math.sin(x * 0.9) * math.cos(y * 0.7) + 1000
        row.append(max(0, min(65535, int(v))))
    pot_idx += [h >> 8 for h in row] + [h & 0xFF for h in row]
write_gif('mesh_hf_heights.pot', 64, 32, pot_idx, hf_palette)

# 16 x 16 x 16 8-bit df3 density for tex_density_file.pov: a soft blob
# plus a tilted ripple (header: three big-endian 16-bit sizes).
n = 16
density = []
for k in range(n):
    for j in range(n):
        for i in range(n):
            x, y, z = [(c + 0.5) / n - 0.5 for c in (i, j, k)]
            r = math.sqrt(x * x + y * y + z * z)
            v = max(0.0, 1 - 2 * r) * 0.7 + 0.3 * (0.5 + 0.5 * math.sin(12 * x + 7 * y - 5 * z))
            density.append(int(round(min(1, v) * 255)))
open('density_blob.df3', 'wb').write(struct.pack('>HHH', n, n, n) + bytes(density))

# 16 x 16 palette PNG for tex_material_map.pov: indices 0..6 (rings
# around an off-centre point, a diagonal band of index 6); the palette's
# colours are unrelated to the textures the indices pick.
mat_palette = [(0, 0, 0), (255, 255, 255), (128, 0, 0), (0, 128, 0), (0, 0, 128),
               (128, 128, 0), (0, 128, 128)]
mat_idx = []
for y in range(16):
    for x in range(16):
        if abs(x - y) <= 1:
            mat_idx.append(6)
        else:
            mat_idx.append(int(math.hypot(x - 5.5, y - 9.5) / 2.5) % 6)
write_png_palette('material_palette.png', 16, 16, mat_idx, mat_palette)

# Dark ramps (red, green on even rows, blue at half) with the gamma chunks
# povray writes or could meet: image_gamma_chunks_v36*.pov.
ramp_levels = [0, 2, 4, 6, 8, 11, 14, 18, 23, 30, 40, 55, 80, 120, 180, 250]
ramp = [v for y in range(4) for x in range(16)
        for v in (ramp_levels[x], ramp_levels[x] if y % 2 == 0 else 0, ramp_levels[x] // 2)]
gama = lambda v: chunk(b'gAMA', struct.pack('>I', v))
srgb = chunk(b'sRGB', b'\0')
write_png('image_ramp_plain.png', 16, 4, ramp, 3)
write_png('image_ramp_srgb.png', 16, 4, ramp, 3, [gama(45455), srgb])
write_png('image_ramp_srgbonly.png', 16, 4, ramp, 3, [srgb])
write_png('image_ramp_g22.png', 16, 4, ramp, 3, [gama(45455)])
write_png('image_ramp_g18.png', 16, 4, ramp, 3, [gama(55556)])
