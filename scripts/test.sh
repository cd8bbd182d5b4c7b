#!/usr/bin/env bash
# The whole test suite, unattended on a fresh Debian 12 (as root): installs
# what is missing, builds, and runs every test (C++ image tests, Python and
# command-line tests) under a virtual X server. Exits non-zero on any failure.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$(softshadows_root)"

# numpy only for the tests' numeric checks.
softshadows_install_packages "${SOFTSHADOWS_PACKAGES[@]}" python3-numpy
softshadows_build

# -noreset: Xvfb would otherwise reset whenever its last client leaves and
# refuse the next test's connection for a moment.
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
  ctest --test-dir build --output-on-failure -j2 "$@"
