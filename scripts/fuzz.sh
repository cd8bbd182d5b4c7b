#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# Runs every fuzz target (Testing/Fuzz) for SECONDS each (default 60), starting
# from its committed corpus, unattended on a fresh Debian 12 (as root): installs
# clang, builds build-fuzz/ (SOFTSHADOWS_FUZZ: libFuzzer, ASan, UBSan) and
# fails if any target crashes, hangs, leaks or trips a sanitizer, printing the
# reproducer's path. The source tree is never written: each run works on a
# copy of the corpus under build-fuzz/fuzz-runs/. docs/testing.md.
#   bash scripts/fuzz.sh [SECONDS] [TARGET...]
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
root=$(softshadows_root)
cd "$root"

seconds=${1:-60}
if ! [[ "$seconds" =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: $0 [SECONDS per target] [TARGET...]" >&2
  exit 2
fi
shift || true

softshadows_install_packages "${SOFTSHADOWS_PACKAGES[@]}" clang-14 libclang-rt-14-dev
build=$(softshadows_build_dir build-fuzz)
if [ ! -f "$build/CMakeCache.txt" ]; then
  # No tests: only the fuzz targets and what they link are configured.
  CC=clang-14 CXX=clang++-14 cmake -S "$root" -B "$build" \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSOFTSHADOWS_FUZZ=ON -DBUILD_TESTING=OFF
fi
cmake --build "$build" -j2 --target fuzzers

# One key=value file per target, written by softshadows_add_fuzzer().
manifests=()
if [ $# -gt 0 ]; then
  for target in "$@"; do
    manifests+=("$build/fuzzers/$target.txt")
  done
else
  manifests=("$build"/fuzzers/*.txt)
fi

failed=()
for manifest in "${manifests[@]}"; do
  if [ ! -f "$manifest" ]; then
    echo "no fuzz target: $manifest" >&2
    exit 2
  fi
  declare -A target=()
  while IFS='=' read -r key value; do
    target[$key]=$value
  done <"$manifest"
  name=${target[name]}

  run="$build/fuzz-runs/$name"
  rm -rf "$run"
  mkdir -p "$run/corpus" "$run/artifacts"
  # Regressions (once a target has any) seed the run too: each is a known
  # hard input.
  cp -r "${target[corpus]}/." "$run/corpus/"
  if [ -d "${target[regressions]}" ]; then
    cp -r "${target[regressions]}/." "$run/corpus/"
  fi
  find "$run/corpus" -name '.*' -type f -delete

  options=(-max_total_time="$seconds" -max_len="${target[max_len]}" -timeout=10
    -rss_limit_mb=4096 -print_final_stats=1 -artifact_prefix="$run/artifacts/")
  if [ -n "${target[dictionary]}" ]; then
    options+=(-dict="${target[dictionary]}")
  fi
  echo "== $name: ${seconds} s (log: $run/fuzz.log)"
  status=0
  LSAN_OPTIONS=suppressions="$root/Testing/Sanitize/lsan.supp":print_suppressions=0 \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "${target[binary]}" "${options[@]}" "$run/corpus" >"$run/fuzz.log" 2>&1 || status=$?
  grep -E '^(stat::number_of_executed_units|stat::average_exec_per_sec|stat::peak_rss_mb|Done )' \
    "$run/fuzz.log" || true
  shopt -s nullglob
  artifacts=("$run"/artifacts/*)
  shopt -u nullglob
  if [ "$status" -ne 0 ] || [ ${#artifacts[@]} -gt 0 ]; then
    echo "-- $name failed (exit $status); the end of its log:"
    tail -n 60 "$run/fuzz.log"
    for artifact in "${artifacts[@]}"; do
      echo "reproducer: $artifact"
      echo "  rerun: ${target[binary]} $artifact"
      echo "  once fixed, keep it: cp $artifact ${target[regressions]}/"
    done
    failed+=("$name")
  fi
  unset target
done

if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzzing found problems in: ${failed[*]}" >&2
  exit 1
fi
echo "fuzzing: no crash in ${#manifests[@]} target(s), ${seconds} s each"
