#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# The whole test suite built with AddressSanitizer and
# UndefinedBehaviorSanitizer (SOFTSHADOWS_SANITIZE) in build-sanitize/,
# unattended on a fresh Debian 12, 13 or unstable (as root): installs what is
# missing, builds, and runs every test under a virtual X server. A sanitizer
# report fails its test; exits non-zero on any failure. Options and
# suppressions: docs/testing.md.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$(softshadows_root)"

# g++ brings the sanitizers' runtimes (libasan8, libubsan1).
softshadows_install_packages "${SOFTSHADOWS_PACKAGES[@]}" "${SOFTSHADOWS_TEST_PACKAGES[@]}"
# Optimized as the tests need it to run in time, with lines in reports.
softshadows_build build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSOFTSHADOWS_SANITIZE=ON
softshadows_ctest build-sanitize "$@"
