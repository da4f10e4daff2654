#!/usr/bin/env bash
# Scene files are found as povray 3.7 finds them (measured with povray
# 3.7.0.10): in the working folder, then in the library path, with ".pov"
# appended when the name has none there. `frameray x/vect2.ini +Lx` from
# the folder above x renders the INI's vect2.pov into the working folder,
# the same frames as a run inside x; `+Ivect2` finds vect2.pov.
#
#     library_path_scene.sh FRAMERAY
set -euo pipefail
frameray="$1"
example=/usr/share/doc/povray/examples/animations/vect2
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$scratch/home" "$scratch/x" "$scratch/inside"
cp "$example/vect2.ini" "$example/vect2.pov" "$scratch/x/"
run() {
    env -u POVINI -u POVRAYOPT -u XDG_CONFIG_HOME HOME="$scratch/home" "$frameray" "$@" \
        +W32 +H24 +KFF2 -GR -GS
}
(cd "$scratch" && run x/vect2.ini +Lx)
(cd "$scratch/x" && run vect2.ini +O../inside/)
for f in vect21.png vect22.png; do
    cmp "$scratch/$f" "$scratch/inside/$f"
done
# Without +Lx povray does not look beside the INI file either.
if (cd "$scratch" && run x/vect2.ini 2>"$scratch/err"); then
    echo "found vect2.pov without the library path" >&2
    exit 1
fi
grep -q "cannot open scene file 'vect2.pov'" "$scratch/err"
# +Ivect2: ".pov" appended, as povray does.
(cd "$scratch/x" && run +Ivect2 +O../appended.png)
test -s "$scratch/appended1.png"
echo "library_path_scene: ok"
