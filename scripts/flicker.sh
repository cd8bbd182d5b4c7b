#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# How much each technique's shadow changes from frame to frame as the light
# turns, against the ray-cast truth's change (scripts/flicker.py): every
# quality scene and a dense isosurface, a few minutes.
#
#   bash scripts/flicker.sh [--techniques ...] [--scenes ...] [--frames N] [--step RADIANS]
#                           [--size WxH] [--samples N] [--gyroid-resolution N] [--shadows JSON] [--json]
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$(softshadows_root)"

softshadows_install_packages "${SOFTSHADOWS_PACKAGES[@]}" python3-numpy
softshadows_build

xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
  /usr/bin/python3 scripts/flicker.py "$(softshadows_build_dir)/bin/softshadows" "$@"
