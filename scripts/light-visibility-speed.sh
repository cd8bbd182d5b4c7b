#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# How fast vtkLightVisibilityFilter casts (scripts/light-visibility-speed.py,
# whose options it passes on), unattended on a fresh Debian 12, 13 or
# unstable (as root): installs what is missing, builds, runs. No window.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$(softshadows_root)"

softshadows_install_packages "${SOFTSHADOWS_PACKAGES[@]}" python3-numpy
softshadows_build

PYTHONPATH="$(softshadows_build_dir)/lib/python3/dist-packages" \
  /usr/bin/python3 scripts/light-visibility-speed.py "$@"
