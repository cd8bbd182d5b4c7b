#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# How each technique's cost grows with triangles, actors and window size,
# unattended on a fresh Debian 12, 13 or unstable (as root): installs what
# is missing, builds, runs scripts/scale.py (the sweeps and options are
# described there) and rewrites docs/benchmarks.md's scale tables and
# docs/benchmarks/scale-*.png. Hours for every sweep: the 10M-triangle
# isosurface and the 3840x2160 window dominate.
#
#   bash scripts/scale.sh [--sweeps triangles,actors,windows] [--cases ...] [--techniques ...]
#                         [--frames N] [--timeout S] [--no-docs]
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$(softshadows_root)"

softshadows_install_packages "${SOFTSHADOWS_PACKAGES[@]}" python3-matplotlib
softshadows_build

xvfb-run -a -s "-screen 0 4096x2304x24 -noreset" \
  /usr/bin/python3 scripts/scale.py "$(softshadows_build_dir)/bin/softshadows" "$@"
