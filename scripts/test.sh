#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# The whole test suite, unattended on a fresh Debian 12 (as root): installs
# what is missing, builds, and runs every test (C++ image tests, Python and
# command-line tests) under a virtual X server. Exits non-zero on any failure.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$(softshadows_root)"

# numpy for the tests' numeric checks, Debian's models for the importers, xdotool
# to drive the viewer's window.
softshadows_install_packages "${SOFTSHADOWS_PACKAGES[@]}" python3-numpy assimp-testmodels xdotool
softshadows_build
softshadows_ctest build "$@"
