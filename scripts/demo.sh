#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# The demo, unattended on a fresh Debian 12, 13 or unstable (as root):
# installs what is missing, builds, and renders Examples/Scenes/demo.json with
# every technique into out/: one PNG per technique and out/gallery.png side by
# side, then prints how long each technique takes per frame.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$(softshadows_root)"

softshadows_install_packages "${SOFTSHADOWS_PACKAGES[@]}"
softshadows_build

softshadows=$(softshadows_build_dir)/bin/softshadows
techniques=$("$softshadows" techniques --specs | paste -sd, -)
xvfb-run -a "$softshadows" gallery Examples/Scenes/demo.json \
  --techniques "$techniques" --output-dir out
