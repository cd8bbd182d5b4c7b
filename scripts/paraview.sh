#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# The ParaView plugin, unattended on a fresh Debian 12, 13 or unstable (as
# root; ParaView 5.11, 5.13 or 6.1): installs what is missing, unpacks
# Debian's paraview, paraview-dev and python3-paraview into
# build-paraview/prefix (on 12 and 13 installing python3-paraview would
# remove python3-vtk9, which the rest of the project needs; ParaView's CMake
# files are relocatable), finds which ParaView it holds, builds the module
# against ParaView's VTK (its own 9.2 or 9.3 in build-paraview/, without the
# programs, C++ tests and image tests run there; unstable's ParaView uses the
# system's VTK, so the module's ordinary build serves), the ordinary build
# (build/, whose softshadows program the plugin's test asks for the
# techniques), builds the plugin (ParaView/) in
# build-paraview/plugin, writes pvpython and pvbatch wrappers that find it
# all, runs the plugin's test in pvpython and its parallel tests (the view's
# and the Light Visibility filter's) in pvbatch on one and two MPI ranks and
# through a pvserver on two ranks, and ends
# with three lines: PLUGIN=, PVPYTHON= and PVBATCH=. Exits non-zero on any
# failure. docs/paraview.md. With --prepare it only installs and unpacks
# (CI does that in the background while it tests something else).
#   bash scripts/paraview.sh [--prepare | CTEST ARGUMENTS...]
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
root=$(softshadows_root)
cd "$root"

packages=(paraview paraview-dev python3-paraview)
build=$(softshadows_build_dir build-paraview)
prefix="$build/prefix"
softshadows_install_packages "${SOFTSHADOWS_PACKAGES[@]}"

if [ ! -f "$prefix/.unpacked" ]; then
  downloads="$build/downloads"
  rm -rf "$downloads" "$prefix"
  mkdir -p "$downloads" "$prefix"
  # apt's sandbox user cannot write into root's folders: download as root.
  # (A fresh machine may have no package lists yet.)
  (cd "$downloads" && { apt-get download -o APT::Sandbox::User=root "${packages[@]}" ||
    { apt-get update && apt-get download -o APT::Sandbox::User=root "${packages[@]}"; }; })
  for deb in "$downloads"/*.deb; do
    dpkg-deb -x "$deb" "$prefix"
  done

  # What the three packages depend on, but for one another: the first of
  # each set of alternatives, without versions.
  depends=()
  for deb in "$downloads"/*.deb; do
    while read -r depend; do
      name=${depend%% *}
      name=${name%%:*}
      case " ${packages[*]} " in *" $name "*) continue ;; esac
      depends+=("$name")
    done < <(dpkg-deb -f "$deb" Depends | tr ',' '\n' | sed 's/|.*//; s/^ *//; /^$/d')
  done
  # mpirun for pvbatch.
  softshadows_install_packages "${depends[@]}" openmpi-bin
  touch "$prefix/.unpacked"
fi
# Debian's ParaView 5.13 and 6.1 name their Python modules with the
# interpreter's suffix (vtkCommonCore.cpython-313-x86_64-linux-gnu.so) where
# their CMake files name them plainly (vtkCommonCore.so), and CMake refuses
# targets whose files are missing: the plain names as links.
while read -r module; do
  plain="${module%%.cpython-*}.so"
  [ -e "$plain" ] || ln -s "$(basename "$module")" "$plain"
done < <(find "$prefix/usr/lib/python3/dist-packages" -name '*.cpython-*.so')
if [ "${1:-}" = --prepare ]; then
  exit 0
fi

# Which ParaView: its CMake package is paraview-5.11, -5.13 or -6.1.
paraview_dir=$(echo "$prefix"/usr/lib/*/cmake/paraview-[0-9]*)
if [ ! -f "$paraview_dir/paraview-config.cmake" ]; then
  echo "scripts/paraview.sh: no ParaView CMake package in $prefix" >&2
  exit 1
fi
libdir=$(dirname "$(dirname "$paraview_dir")")
echo "ParaView ${paraview_dir##*/paraview-} from Debian's packages" >&2

if [ -f "$paraview_dir/vtk/vtk-config.cmake" ]; then
  # ParaView's own VTK (5.11: 9.2, 5.13: 9.3): the module built against it,
  # and its C++ tests run there. The Python tests need ParaView's own Python,
  # which conflicts with the system's vtkmodules; the install test builds
  # against the system VTK.
  module_build=build-paraview
  softshadows_build build-paraview "-DVTK_DIR=$paraview_dir/vtk" -DSOFTSHADOWS_APPLICATIONS=OFF
  softshadows_ctest build-paraview -E '^(Python|Install)\.' "$@"
else
  # ParaView built on the system's VTK (6.1 on Debian unstable): the
  # module's ordinary build is the one, tested by scripts/test.sh.
  module_build=build
fi
# The ordinary build's softshadows program lists the techniques the plugin's
# panel must offer (test_plugin.py).
softshadows_build build
softshadows=$(softshadows_build_dir build)/bin/softshadows

# The module installed, and the plugin built against it and ParaView.
install="$build/install"
cmake --install "$(softshadows_build_dir "$module_build")" --prefix "$install" >/dev/null
plugin_build="$build/plugin"
if [ ! -f "$plugin_build/CMakeCache.txt" ] || [ ! -f "$plugin_build/Makefile" ]; then
  cmake -S "$root/ParaView" -B "$plugin_build" -DCMAKE_BUILD_TYPE=Release \
    "-DParaView_DIR=$paraview_dir" "-DSoftShadows_DIR=$install/lib/cmake/softshadows"
fi
cmake --build "$plugin_build" -j2
plugin="$plugin_build/lib/SoftShadows/SoftShadows.so"

# pvpython and pvbatch from the prefix, with its libraries and Python
# modules (before the system's vtkmodules) and the module's libraries.
for program in pvpython pvbatch pvserver; do
  cat >"$build/$program" <<WRAPPER
#!/bin/sh
# $program from Debian's ParaView unpacked in $prefix (scripts/paraview.sh).
export LD_LIBRARY_PATH="$libdir:$install/lib\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}"
export PYTHONPATH="$prefix/usr/lib/python3/dist-packages\${PYTHONPATH:+:\$PYTHONPATH}"
exec "$prefix/usr/bin/$program" "\$@"
WRAPPER
  chmod +x "$build/$program"
done

xvfb() { xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$@"; }
xvfb "$build/pvpython" --force-offscreen-rendering "$root/Testing/ParaView/test_plugin.py" "$plugin" \
  "$softshadows"
# Across MPI ranks: one rank's images, then two ranks' checked against them.
parallel="$build/parallel-test"
rm -rf "$parallel"
mkdir -p "$parallel"
xvfb "$build/pvbatch" --force-offscreen-rendering "$root/Testing/ParaView/test_parallel.py" \
  "$plugin" "$parallel"
xvfb timeout 300 mpirun --allow-run-as-root --oversubscribe -np 2 "$build/pvbatch" \
  --force-offscreen-rendering "$root/Testing/ParaView/test_parallel.py" "$plugin" "$parallel"
# The Light Visibility filter: one rank's values checked, then two ranks'
# against them.
xvfb "$build/pvbatch" --force-offscreen-rendering "$root/Testing/ParaView/test_light_visibility.py" \
  "$plugin" "$parallel"
xvfb timeout 300 mpirun --allow-run-as-root --oversubscribe -np 2 "$build/pvbatch" \
  --force-offscreen-rendering "$root/Testing/ParaView/test_light_visibility.py" "$plugin" \
  "$parallel"
# Through a pvserver on two ranks, on a free port; the server exits when
# the client leaves (timeout: in case the client never came).
port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("localhost", 0)); print(s.getsockname()[1])')
xvfb timeout 300 mpirun --allow-run-as-root --oversubscribe -np 2 "$build/pvserver" \
  --force-offscreen-rendering "--server-port=$port" >"$parallel/pvserver.log" 2>&1 &
server=$!
if ! xvfb "$build/pvpython" "$root/Testing/ParaView/test_client_server.py" "$plugin" \
  "$parallel" "$port"; then
  kill "$server" 2>/dev/null || true
  exit 1
fi
wait "$server" || { cat "$parallel/pvserver.log"; exit 1; }
# The README's examples, as a user runs them.
xvfb "$build/pvpython" --force-offscreen-rendering "$root/Examples/Python/paraview_shadows.py" \
  "$plugin" "$build/paraview_shadows.png"
xvfb "$build/pvpython" --force-offscreen-rendering \
  "$root/Examples/Python/paraview_light_visibility.py" "$plugin" "$build/paraview_light_visibility.png"
echo "PLUGIN=$plugin"
echo "PVPYTHON=$build/pvpython"
echo "PVBATCH=$build/pvbatch"
