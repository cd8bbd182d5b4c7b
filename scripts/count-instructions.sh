#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# Instructions a frame, counted by callgrind: the way to compare two builds
# on a shared machine, where wall-clock ratios move by 10-20% between runs
# and instruction counts repeat to 0.01%.
#
#   bash scripts/count-instructions.sh [SCENE] [TECHNIQUE] [WxH]
#
# defaults Examples/Scenes/demo.json, contact, 512x512. Prints the
# instructions of one frame of `hard` and of TECHNIQUE, and their ratio:
# `softshadows bench` over 1 and over 5 frames (each draws `hard` and
# TECHNIQUE), the difference divided by 4, so start-up, shader compilation
# and the frame before each technique's block (bench draws a technique's
# frames in blocks of up to 5) cancel. Each count follows a counted warm-up
# run of 1 frame: Mesa's shader cache is keyed by the CPU, and the one
# valgrind presents differs from the machine's. A few minutes a technique.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$(softshadows_root)"

scene=${1:-Examples/Scenes/demo.json}
technique=${2:-contact}
size=${3:-512x512}

softshadows_install_packages "${SOFTSHADOWS_PACKAGES[@]}" valgrind
softshadows_build

# Total instructions of `bench` with techniques $1 over $2 frames.
count() {
  local out
  out=$(mktemp)
  xvfb-run -a valgrind --tool=callgrind --callgrind-out-file="$out" \
    "$(softshadows_build_dir)/bin/softshadows" bench "$scene" --techniques "$1" --size "$size" --frames "$2" \
    >/dev/null 2>&1
  callgrind_annotate "$out" | awk '/PROGRAM TOTALS/ { gsub(",", "", $1); print $1 }'
  rm -f "$out"
}

# Instructions of one frame of `hard` plus one of $1 (just `hard` for hard).
per_frame() {
  count "$1" 1 >/dev/null
  local one five
  one=$(count "$1" 1)
  five=$(count "$1" 5)
  echo $(((five - one) / 4))
}

hard=$(per_frame hard)
both=$(per_frame "$technique")
awk -v hard="$hard" -v both="$both" -v name="$technique" 'BEGIN {
  printf "hard        %8.1f M instructions a frame\n", hard / 1e6
  printf "%-11s %8.1f M instructions a frame, %.3f x hard\n", name, (both - hard) / 1e6,
    (both - hard) / hard
}'
