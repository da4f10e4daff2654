#!/usr/bin/env bash
# Installs the dependencies, builds frameray and renders the bundled demo
# animation into frames/demo/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh build
build/bin/frameray ini/demo.ini
echo "demo frames written to frames/demo/"
