#!/usr/bin/env bash
# Installs every Debian package frameray needs to build, test and compare
# against the reference povray 3.7. Idempotent: does nothing when all are
# present. Needs root (or sudo) only when something is missing.
set -euo pipefail

packages=(
    cmake g++ make ccache
    libembree-dev libtbb-dev
    libopenimageio-dev openimageio-tools libopenexr-dev libpng-dev libjpeg-dev
    libspdlog-dev libfmt-dev libfreetype-dev
    googletest libgtest-dev
    povray povray-includes povray-examples
    python3 python3-numpy python3-matplotlib
    # Preview_Video runs the ffmpeg program (libx264, libvpx); the contact
    # sheet's test looks at the page in headless Chromium.
    ffmpeg chromium
)

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "setup: all ${#packages[@]} packages present"
    exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
