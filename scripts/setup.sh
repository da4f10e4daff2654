#!/usr/bin/env bash
# Installs every Debian package frameray needs to build, test and compare
# against the reference povray 3.7, and the npm packages of the tests.
# Idempotent: does nothing when all are present. Needs root (or sudo) only
# when a Debian package is missing.
set -euo pipefail
cd "$(dirname "$0")/.."

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
    # The cluster.slurm test starts a one-node Slurm cluster (issue 28).
    slurm-wlm munge
)

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done
# The cluster.kubernetes_job test runs node with npm packages; a node that
# did not come from Debian (with its own npm) is used as it is.
if ! command -v node > /dev/null || ! command -v npm > /dev/null; then
    missing+=(nodejs npm)
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
if [ ${#missing[@]} -eq 0 ]; then
    echo "setup: all ${#packages[@]} packages present"
else
    echo "setup: installing ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    $SUDO apt-get update -qq
    $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# npm packages of the tests, as their lock file pins them (once per lock).
kube=tests/cluster/kubernetes
stamp="$kube/node_modules/.frameray-lock-sha256"
want=$(sha256sum "$kube/package-lock.json" | cut -d' ' -f1)
if [ "$(cat "$stamp" 2>/dev/null)" != "$want" ]; then
    echo "setup: npm ci in $kube"
    (cd "$kube" && npm ci --no-audit --no-fund --loglevel=error)
    echo "$want" > "$stamp"
else
    echo "setup: npm packages of $kube present"
fi
