#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# Runs a command of the project's on another Debian release, in a root of
# that release made with debootstrap from Debian's registry and kept between
# runs, with this checkout at the same path inside it, e.g.
#   bash scripts/debian.sh trixie bash scripts/test.sh
# RELEASE is bookworm (12), trixie (13) or sid (unstable). Roots live in
# $SOFTSHADOWS_ROOTS (default /var/lib/softshadows/roots); build folders
# get the release's name (build-trixie/, build-paraview-trixie/...), so that
# the releases' builds sit side by side in the checkout. Mounts /proc, /sys,
# /dev, /dev/pts, /dev/shm and the host's /tmp (so that virtual X servers of
# the host and of roots pick different displays) in a mount namespace of its
# own, and unmounts everything it mounted when it ends, also on failure or
# Ctrl-C. Several runs may use one root at once. As root only.
#   bash scripts/debian.sh RELEASE [COMMAND...]   (default: an interactive shell)
set -euo pipefail

usage() {
  echo "usage: bash scripts/debian.sh bookworm|trixie|sid [COMMAND...]" >&2
  exit 2
}
[ $# -ge 1 ] || usage
case "$1" in
  bookworm | 12) release=bookworm ;;
  trixie | 13) release=trixie ;;
  sid | unstable) release=sid ;;
  *) usage ;;
esac
shift
if [ "$(id -u)" -ne 0 ]; then
  echo "scripts/debian.sh: must run as root (debootstrap, chroot and mount need it)" >&2
  exit 1
fi
[ $# -ge 1 ] || set -- bash

# The mounts are made in a mount namespace of this run's own: the host and
# other runs in the same root do not see them, and they go with the run
# even if it is killed.
if [ -z "${SOFTSHADOWS_DEBIAN_NAMESPACE:-}" ]; then
  SOFTSHADOWS_DEBIAN_NAMESPACE=1 exec unshare --mount --propagation private -- \
    bash "${BASH_SOURCE[0]}" "$release" "$@"
fi

checkout=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
roots=${SOFTSHADOWS_ROOTS:-/var/lib/softshadows/roots}
mkdir -p "$roots"
target="$(cd "$roots" && pwd -P)/$release"
mirror=${SOFTSHADOWS_MIRROR:-http://deb.debian.org/debian}

mounted=()
# Unmounts, newest first, what this run mounted; processes left inside the
# root (a virtual X server, an MPI daemon) are ended first, since they would
# keep their mounts busy.
cleanup() {
  local status=$? pid i killed=0 namespace
  trap - EXIT INT TERM HUP
  namespace=$(readlink /proc/self/ns/mnt)
  for pid in /proc/[0-9]*; do
    # This run's own: in the root and in this run's mount namespace.
    if [ "$(readlink "$pid/root" 2>/dev/null)" = "$target" ] &&
      [ "$(readlink "$pid/ns/mnt" 2>/dev/null)" = "$namespace" ]; then
      kill "${pid#/proc/}" 2>/dev/null && killed=1
    fi
  done
  [ "$killed" -eq 0 ] || sleep 1
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
    umount "${mounted[i]}" 2>/dev/null || umount -l "${mounted[i]}" ||
      echo "scripts/debian.sh: could not unmount ${mounted[i]}" >&2
  done
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
trap 'exit 129' HUP

# mount_at SOURCE PATH-IN-ROOT [MOUNT OPTIONS...]: a bind mount unless
# options are given; remembered for cleanup.
mount_at() {
  local source=$1 path="$target$2"
  shift 2
  mkdir -p "$path"
  if [ $# -eq 0 ]; then
    mount --bind "$source" "$path"
  else
    mount "$@" "$source" "$path"
  fi
  mounted+=("$path")
}

# The root, made once. A root whose making was cut short has no marker and is
# made again from scratch.
if [ ! -f "$target/.softshadows-root" ]; then
  if ! command -v debootstrap >/dev/null 2>&1; then
    echo "Installing: debootstrap" >&2
    DEBIAN_FRONTEND=noninteractive apt-get update
    DEBIAN_FRONTEND=noninteractive apt-get install -y debootstrap
  fi
  rm -rf "$target"
  mkdir -p "$target"
  echo "Making a $release root in $target" >&2
  debootstrap --variant=minbase "$release" "$target" "$mirror" >&2
  # sid's Release file in the registry can be past its Valid-Until date.
  echo 'Acquire::Check-Valid-Until "false";' >"$target/etc/apt/apt.conf.d/99softshadows"
  touch "$target/.softshadows-root"
fi
# Name resolution as the host has it.
cp -L /etc/resolv.conf "$target/etc/resolv.conf" 2>/dev/null || true

mount_at proc /proc -t proc
mount_at sysfs /sys -t sysfs -o ro
mount_at /dev /dev
mount_at /dev/pts /dev/pts
mount_at /dev/shm /dev/shm
mount_at /tmp /tmp
mount_at "$checkout" "$checkout"

# A clean environment, but for CI and the terminal; build folders named by
# release (scripts/common.sh).
env=(HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin
  LANG=C.UTF-8 TERM="${TERM:-dumb}" SOFTSHADOWS_BUILD_SUFFIX="-$release")
[ -z "${CI:-}" ] || env+=(CI="$CI")
status=0
chroot "$target" /usr/bin/env -i "${env[@]}" /bin/bash -c 'cd "$1" && shift && "$@"' \
  bash "$checkout" "$@" || status=$?
exit "$status"
