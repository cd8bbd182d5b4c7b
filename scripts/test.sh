#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# The whole test suite, unattended on a fresh Debian 12, 13 or unstable (as
# root): installs what is missing, builds, and runs every test (C++ image
# tests, Python and command-line tests) under a virtual X server. Exits
# non-zero on any failure.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$(softshadows_root)"

softshadows_install_packages "${SOFTSHADOWS_PACKAGES[@]}" "${SOFTSHADOWS_TEST_PACKAGES[@]}"
softshadows_build
softshadows_ctest build "$@"
