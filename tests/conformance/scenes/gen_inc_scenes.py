#!/usr/bin/env python3
"""Writes the inc_*.pov conformance scenes: every texture, pigment, finish,
normal, interior, material, colour map, colour and object that a standard
POV-Ray include file declares, each applied to (or being) one object of a
grid, so that frameray's reading of the include files can be compared with
POV-Ray's render of the same scene.

    tests/conformance/scenes/gen_inc_scenes.py [--include-dir DIR]

Scenes are regenerated from the include files installed with POV-Ray 3.7
(/usr/share/povray-3.7/include); the list of what each file declares is read
from the file itself, so a scene's items follow the file. Items that frameray
cannot render yet are named in SKIP with the reason and go in the header
comment of the scene instead of its grid. Run from anywhere; rewrites
scenes/inc_*.pov (except the hand-written inc_shapes_macros.pov and
inc_shapes3_macros.pov, which call the macros of shapes.inc and shapes3.inc)
and prints the manifest lines.
"""
import argparse
import math
import os
import re
import textwrap

HERE = os.path.dirname(os.path.abspath(__file__))

# Per item kind: how one declared identifier X is put on the unit sphere.
WRAP = {
    'texture': 'sphere { 0, 1 texture { %s } }',
    'pigment': 'sphere { 0, 1 pigment { %s } }',
    'finish': 'sphere { 0, 1 pigment { rgb <0.8, 0.55, 0.3> } finish { %s } }',
    'normal': 'sphere { 0, 1 pigment { rgb 0.8 } normal { %s } }',
    # An interior only shows through a transparent surface.
    'interior': 'sphere { 0, 1 pigment { rgbf <1, 1, 1, 0.9> } '
                'finish { diffuse 0.1 specular 0.6 roughness 0.005 } interior { %s } }',
    'material': 'sphere { 0, 1 material { %s } }',
    'color': 'sphere { 0, 1 pigment { color %s } }',
    # Colour maps (woodmaps.inc, textures.inc) are meant for wood-like
    # patterns; the turbulence exercises the noise as well.
    'color_map': 'sphere { 0, 1 pigment { wood turbulence 0.08 color_map { %s } '
                 'scale 0.25 rotate <70, 20, 0> } }',
    # Objects of shapes*.inc: infinite ones are clipped to the cell.
    'object': 'object { %s clipped_by { box { -1.2, 1.2 } } scale 0.75 '
              'texture { pigment { rgb <0.9, 0.7, 0.4> } finish { phong 0.5 } } '
              'rotate <-20, 35, 0> }',
}
KINDS = {
    'texture': 'texture', 'pigment': 'pigment', 'finish': 'finish', 'normal': 'normal',
    'interior': 'interior', 'material': 'material', 'color_map': 'color_map',
    'colour_map': 'color_map', 'color': 'color', 'colour': 'color', 'rgb': 'color',
    'rgbf': 'color', 'rgbt': 'color', 'rgbft': 'color', 'srgb': 'color',
    'sky_sphere': 'sky_sphere',
}
OBJECTS = {'sphere', 'box', 'cone', 'cylinder', 'plane', 'quadric', 'intersection', 'union',
           'merge', 'difference', 'object', 'torus', 'poly', 'quartic', 'superellipsoid',
           'isosurface', 'prism', 'lathe', 'sor', 'blob', 'mesh', 'mesh2', 'text', 'disc'}


def strip_comments(text):
    """Blanks out comments, keeping string literals intact."""
    return re.sub(r'//[^\n]*|/\*.*?\*/|"(?:[^"\\]|\\.)*"',
                  lambda m: m.group(0) if m.group(0).startswith('"') else ' ', text, flags=re.S)


# Features frameray still refuses (`not supported yet`): an item whose
# declaration uses one, directly or through another identifier, is left
# out of the grid with the reason.
REFUSED = {
    'crand': 'crand (povray adds per-pixel random noise to the colour)',
    'dispersion': 'dispersion',
    'caustics': 'caustics',
    'irid': 'irid',
}


def declarations(path, known, refused):
    """(name, kind) of the identifiers declared outside macros, in order.
    An identifier declared as another identifier takes that one's kind.
    refused[name] collects the REFUSED features each declaration uses."""
    text = strip_comments(open(path, encoding='latin-1').read())
    stack = []
    found = []
    directives = list(re.finditer(r'#\s*(declare|macro|end|if|ifdef|ifndef|while|for|switch)\b', text))
    for index, m in enumerate(directives):
        word = m.group(1)
        if word in ('macro', 'if', 'ifdef', 'ifndef', 'while', 'for', 'switch'):
            stack.append(word)
        elif word == 'end':
            if stack:
                stack.pop()
        elif 'macro' not in stack:
            d = re.match(r'\s*([A-Za-z_]\w*)\s*=\s*([A-Za-z_]\w*|<|[-+0-9.])', text[m.end():])
            if not d:
                continue
            name, first = d.groups()
            if name.endswith('_Inc_Temp') or name.endswith('_Temp'):
                continue
            if first in KINDS:
                kind = KINDS[first]
            elif first in OBJECTS:
                kind = 'object'
            else:
                kind = known.get(first, 'other')
            known[name] = kind
            end = directives[index + 1].start() if index + 1 < len(directives) else len(text)
            body = text[m.end() + d.start(2):end]
            uses = {f for f in REFUSED if re.search(r'\b%s\b' % f, body)}
            for word in set(re.findall(r'[A-Za-z_]\w*', body)):
                uses |= refused.get(word, set())
            refused[name] = uses
            if name not in [n for n, _ in found]:
                found.append((name, kind))
            else:
                found = [(n, kind if n == name else k) for n, k in found]
    return found


def grid(count):
    """Smallest 4:3 grid of columns x rows holding count cells."""
    cols = 4
    while cols * int(cols * 0.75) < count:
        cols += 1
    return cols, int(cols * 0.75)


def write_scene(name, title, includes, items, width, height, notes, extra=''):
    cols, rows = grid(len(items))
    cell = 2.5
    span_x = cols * cell
    span_y = span_x * 0.75
    lines = [
        '// %s' % title,
        '// Generated by gen_inc_scenes.py from the installed include files: edit',
        '// the generator, not this file. Grid order: left to right, top to bottom.',
    ]
    lines += ['// ' + line for n in notes for line in textwrap.wrap(n, 74)]
    lines += [
        '#version 3.7;',
        'global_settings { assumed_gamma 1.0 }',
        '#include "colors.inc"',
    ]
    lines += ['#include "%s"' % inc for inc in includes]
    lines += [
        'camera { orthographic location <0, 0, -30> look_at <0, 0, 0>',
        '  right %g * x up %g * y }' % (span_x, span_y),
        'light_source { <-30, 40, -60> rgb 1 }',
        'light_source { <40, 10, -30> rgb 0.3 shadowless }',
        'background { rgb <0.25, 0.3, 0.4> }',
        '// A checkered backdrop for transparent and refracting items.',
        'plane { z, 3 pigment { checker rgb 0.9 rgb 0.5 scale %g } }' % (cell / 2),
        extra,
    ]
    for i, (ident, kind) in enumerate(items):
        col, row = i % cols, i // cols
        x = (col - (cols - 1) / 2) * cell
        y = ((rows - 1) / 2 - row) * cell
        lines.append('object { %s translate <%g, %g, 0> } // %s' % (WRAP[kind] % ident, x, y, ident))
    with open(os.path.join(HERE, name + '.pov'), 'w') as f:
        f.write('\n'.join(l for l in lines if l != '') + '\n')
    return '%-28s 0.99  +W%d +H%d' % (name, width, height)


def chunks(items, most):
    """Splits items into the fewest nearly equal parts of at most `most`."""
    parts = max(1, math.ceil(len(items) / most))
    size = math.ceil(len(items) / parts)
    return [items[i:i + size] for i in range(0, len(items), size)]


# Items left out of the grids: identifier -> why. Each becomes a comment in
# its scene's header (and the item is rendered nowhere).
SKIP = {}

# (scene base name, include line(s), files whose declarations are the items,
# width, height, items per scene).
FILES = [
    ('inc_textures', ['textures.inc'], ['textures.inc'], 480, 360, 48),
    ('inc_woods', ['woods.inc'], ['woods.inc'], 480, 360, 48),
    ('inc_woodmaps', ['woodmaps.inc'], ['woodmaps.inc'], 480, 360, 48),
    ('inc_stones1', ['stones.inc'], ['stones1.inc'], 480, 360, 48),
    ('inc_stones2', ['stones.inc'], ['stones2.inc'], 480, 360, 48),
    ('inc_metals', ['metals.inc'], ['metals.inc'], 480, 360, 48),
    ('inc_golds', ['golds.inc'], ['golds.inc'], 480, 360, 48),
    ('inc_glass', ['glass.inc'], ['glass_old.inc', 'glass.inc'], 480, 360, 48),
    # Interiors apart: strong fades differ a little (see INTERIORS_NOTE).
    ('inc_glass_interiors', ['glass.inc'], ['glass_old.inc', 'glass.inc'], 320, 240, 48),
    ('inc_finish', ['finish.inc'], ['finish.inc'], 320, 240, 48),
    ('inc_skies', ['skies.inc'], ['skies.inc'], 320, 240, 48),
    ('inc_stars', ['stars.inc'], ['stars.inc'], 480, 360, 48),
    ('inc_shapes', ['shapes.inc'], ['shapes_old.inc', 'shapes.inc'], 480, 360, 48),
    ('inc_shapes2', ['shapes.inc', 'shapes2.inc'], ['shapes2.inc'], 320, 240, 48),
    ('inc_shapes3', ['shapes3.inc'], ['shapes3.inc'], 320, 240, 48),
]


INTERIORS_NOTE = ('inside the spheres with the strongest fades povray is about 7/255 '
                  'brighter where the backdrop shows through (cause not found; a '
                  'plain background through them matches).')


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--include-dir', default='/usr/share/povray-3.7/include')
    args = parser.parse_args()
    manifest = []
    for base, includes, sources, width, height, most in FILES:
        known = {}
        refused = {}
        items = []
        for source in sources:
            items += declarations(os.path.join(args.include_dir, source), known, refused)
        skip = dict(SKIP)
        for n, k in items:
            if refused.get(n) and k in WRAP:
                skip[n] = 'uses ' + ', '.join(REFUSED[f] for f in sorted(refused[n])) + \
                    ', not supported yet'
        drawn = [(n, k) for n, k in items if k in WRAP and n not in skip]
        notes = ['Left out: %s: %s.' % (n, skip[n]) for n, _ in items if n in skip]
        if base == 'inc_glass':
            drawn = [(n, k) for n, k in drawn if k != 'interior']
        elif base == 'inc_glass_interiors':
            drawn = [(n, k) for n, k in drawn if k == 'interior']
            notes.append(INTERIORS_NOTE)
        others = [n for n, k in items if k not in WRAP and k != 'sky_sphere']
        if others:
            notes.append('Not drawn (floats, vectors, maps): ' + ', '.join(others))
        parts = chunks(drawn, most)
        for i, part in enumerate(parts):
            name = base if len(parts) == 1 else '%s_%d' % (base, i + 1)
            title = 'Every item declared in %s%s on a sphere of the grid%s.' % (
                ' and '.join(sources), '' if len(parts) == 1 else ' (part %d of %d)' % (i + 1, len(parts)),
                '')
            manifest.append(write_scene(name, title, includes, part, width, height,
                                        notes if i == 0 else []))
        for n, k in items:
            if k == 'sky_sphere' and n not in SKIP:
                manifest.append(write_sky(base + '_' + n, includes, n))
    print('\n'.join(manifest))


def write_sky(name, includes, ident):
    """A sky_sphere fills the background: one scene each, looking at the
    horizon and up, with a sphere to show it is behind everything."""
    lines = [
        '// The sky_sphere %s of %s.' % (ident, includes[0]),
        '// Generated by gen_inc_scenes.py: edit the generator, not this file.',
        '#version 3.7;',
        'global_settings { assumed_gamma 1.0 }',
        '#include "colors.inc"',
    ] + ['#include "%s"' % inc for inc in includes] + [
        'camera { location <0, 1, -4> look_at <0, 2.2, 0> angle 90 }',
        'light_source { <-30, 40, -60> rgb 1 }',
        'sky_sphere { %s }' % ident,
        'plane { y, 0 pigment { checker rgb 0.9 rgb 0.5 } }',
        'sphere { <0, 1, 0>, 1 pigment { rgb <0.8, 0.55, 0.3> } finish { reflection 0.3 } }',
    ]
    with open(os.path.join(HERE, name + '.pov'), 'w') as f:
        f.write('\n'.join(lines) + '\n')
    return '%-28s 0.99  +W160 +H120' % name


if __name__ == '__main__':
    main()
