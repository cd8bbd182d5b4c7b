# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# shellcheck shell=bash
# Shared by scripts/*.sh: the Debian packages the project needs and a
# function that installs the missing ones. Source it; it changes nothing by
# itself.

# Build tools, VTK (C++ and Python), GLM, OpenMesh, JSON, Embree, and an X
# server without a screen with Mesa's drivers for rendering. The names are
# the same on Debian 12, 13 and unstable (VTK 9.1, 9.3, 9.6; Embree 3, 4, 4).
# shellcheck disable=SC2034 # read by the scripts that source this file
SOFTSHADOWS_PACKAGES=(
  cmake g++ make
  libvtk9-dev python3-vtk9
  libglm-dev libopenmesh-dev nlohmann-json3-dev libembree-dev
  xvfb xauth libgl1-mesa-dri
)

# What the tests use besides: numpy for their numeric checks, Debian's
# models for the importers, xdotool to drive the viewer's window, MPI for
# the visibility filter split among processes, and PyVista, which Debian
# has from 13 on.
SOFTSHADOWS_TEST_PACKAGES=(python3-numpy assimp-testmodels xdotool openmpi-bin python3-mpi4py)
if [ "$(. /etc/os-release && echo "${VERSION_CODENAME:-}")" != bookworm ]; then
  SOFTSHADOWS_TEST_PACKAGES+=(python3-pyvista)
fi

# The repository's root folder, wherever the caller runs from.
softshadows_root() {
  (cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
}

# Installs those of the packages given that are not installed yet, e.g.
#   softshadows_install_packages "${SOFTSHADOWS_PACKAGES[@]}"
# Runs apt-get only when something is missing: as root, or through sudo.
softshadows_install_packages() {
  local missing=()
  local package
  for package in "$@"; do
    # dpkg -s also lists removed packages whose configuration remains.
    if ! dpkg -s "$package" 2>/dev/null | grep -q '^Status: install ok installed'; then
      missing+=("$package")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return 0
  fi

  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    if ! command -v sudo >/dev/null 2>&1; then
      echo "Missing packages: ${missing[*]}; run as root to install them." >&2
      return 1
    fi
    sudo=(sudo)
  fi
  echo "Installing: ${missing[*]}" >&2
  # Waiting for the package database if another install holds it (CI
  # prepares other releases' roots while it installs here).
  local wait=(-o DPkg::Lock::Timeout=600)
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get "${wait[@]}" update
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get "${wait[@]}" install -y "${missing[@]}"
}

# The build folder NAME (default build) of the checkout, e.g. build-paraview.
# Inside a root of another release made by scripts/debian.sh, the folder
# carries the release's name (build-trixie, build-paraview-trixie), so that
# each release keeps its own builds beside the host's.
softshadows_build_dir() {
  echo "$(softshadows_root)/${1:-build}${SOFTSHADOWS_BUILD_SUFFIX:-}"
}

# Configures FOLDER (default build; Release and the cmake options given after
# it) unless it is configured already, then builds it, e.g.
#   softshadows_build build-sanitize -DSOFTSHADOWS_SANITIZE=ON
softshadows_build() {
  local build
  build=$(softshadows_build_dir "${1:-build}")
  shift || true
  # (A configure that failed leaves a cache but no Makefile.)
  if [ ! -f "$build/CMakeCache.txt" ] || [ ! -f "$build/Makefile" ]; then
    cmake -S "$(softshadows_root)" -B "$build" -DCMAKE_BUILD_TYPE=Release "$@"
  fi
  cmake --build "$build" -j2
}

# Runs ctest in FOLDER (default build) under a virtual X server, with any
# further ctest arguments.
softshadows_ctest() {
  local build
  build=$(softshadows_build_dir "${1:-build}")
  shift || true
  # -noreset: Xvfb would otherwise reset whenever its last client leaves and
  # refuse the next test's connection for a moment.
  xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
    ctest --test-dir "$build" --output-on-failure -j2 "$@"
}
