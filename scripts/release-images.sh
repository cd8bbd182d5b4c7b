#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# Every technique's pictures of the demo scene, shaded and shadow-only, on
# the release this runs on, into out/releases/<release>/ (builds first), so
# that releases can be compared (scripts/compare-releases.py;
# docs/releases.md):
#   bash scripts/release-images.sh [SCENE.json] [WxH]
#   bash scripts/debian.sh trixie bash scripts/release-images.sh
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$(softshadows_root)"

scene=${1:-Examples/Scenes/demo.json}
size=${2:-320x240}
softshadows_install_packages "${SOFTSHADOWS_PACKAGES[@]}"
softshadows_build

release=$(. /etc/os-release && echo "${VERSION_CODENAME:-unknown}")
# Debian unstable names the next release; sid is what it is called here.
[ -z "$(grep -o sid /etc/debian_version)" ] || release=sid
folder="out/releases/$release"
mkdir -p "$folder"
softshadows=$(softshadows_build_dir)/bin/softshadows
for spec in $("$softshadows" techniques --specs); do
  name=${spec//:/-}
  xvfb-run -a "$softshadows" render "$scene" --technique "$spec" --size "$size" \
    --output "$folder/$name.png" --quiet
  # VTK's own pass has no shadow-only output.
  if [ "$spec" != vtk ]; then
    xvfb-run -a "$softshadows" render "$scene" --technique "$spec" --size "$size" \
      --shadow-only --output "$folder/$name-shadow.png" --quiet
  fi
done
echo "$folder"
