#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# Quality against physics, unattended on a fresh Debian 12, 13 or unstable (as root):
# installs what is missing, builds, and measures every technique on every
# scene of Examples/Scenes/quality against the ray-cast truth. Prints the
# table and rewrites docs/quality.md's table, its pictures
# (docs/quality/<scene>.png) and the plot of RMSE against frame time
# (docs/quality/rmse-vs-time.png). A few minutes.
#
#   bash scripts/quality.sh [--no-docs]
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$(softshadows_root)"

softshadows_install_packages "${SOFTSHADOWS_PACKAGES[@]}" python3-numpy python3-matplotlib
softshadows_build

xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
  /usr/bin/python3 scripts/quality.py "$(softshadows_build_dir)/bin/softshadows" "$@"
