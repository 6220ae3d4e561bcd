#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Build one LAMMPS release from Debian's source package and install it under /var/cache/tdem,
# for the tdem tests and benchmarks against LAMMPS versions that this Debian does not ship.
#
#   bash tools/lammps_from_source.sh UPSTREAM        e.g. 20260704 (4Jul2026), 20250204 (4Feb2025)
#
# The source comes through apt only: `apt-get source --tar-only lammps=VERSION` from the deb-src
# suites that tools/setup.sh enabled (apt checks the tarball against the signed Sources index).
# Result, reused by every later run (marker .complete), one directory per version:
#   $TDEM_DEPS_DIR/lammps-UPSTREAM/           the installed LAMMPS: bin/lmp, lib/liblammps.so,
#                                             lib/cmake/LAMMPS (shared, PLUGIN enabled), and
#   $TDEM_DEPS_DIR/lammps-UPSTREAM/source/    its unpacked source tree (source/src: the headers)
# This directory is what tdem's CMake takes in TDEM_LAMMPS_EXTRA.
# Packages: GRANULAR RIGID MOLECULE PLUGIN (what the tdem tests use besides the core).
# Prints progress; takes 10-20 minutes on 2 cores.
set -euo pipefail

up="${1:?usage: lammps_from_source.sh UPSTREAM_VERSION (e.g. 20260704)}"
deps_dir="${TDEM_DEPS_DIR:-/var/cache/tdem}"
jobs="${TDEM_JOBS:-$(nproc)}"
prefix="$deps_dir/lammps-$up"
src="$prefix/source"
bld="$deps_dir/lammps-$up-build"
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
log() { printf '[tdem lammps %s] %s\n' "$up" "$*"; }

if [ -f "$prefix/.complete" ] && [ -f "$src/.complete" ]; then
  log "cached: $prefix"
  exit 0
fi
$SUDO mkdir -p "$deps_dir"
$SUDO chown "$(id -u):$(id -g)" "$deps_dir"

# 1. source --------------------------------------------------------------------------------------
if [ ! -f "$src/.complete" ]; then
  # the newest Debian revision of this upstream version that the enabled deb-src suites carry
  ver="$(apt-cache showsrc lammps 2>/dev/null | awk '/^Version:/ {print $2}' | grep -E "^([0-9]+:)?$up[+.~-]" |
         sort -V | tail -n 1 || true)"
  if [ -z "$ver" ]; then
    log "ERROR: no Debian source package of LAMMPS $up in the enabled deb-src suites"
    log "       (versions seen: $(apt-cache showsrc lammps 2>/dev/null | awk '/^Version:/ {printf "%s ", $2}'))"
    log "       run tools/setup.sh first; it enables deb-src for this Debian and the newer suites"
    exit 1
  fi
  dl="$deps_dir/download-$up"
  rm -rf "$dl" && mkdir -p "$dl"
  log "fetching the source of lammps $ver through apt (orig tarball only)"
  # --tar-only: the suites' .dsc is not needed (and was seen to answer 404 where the tarball did not)
  (cd "$dl" && apt-get source --download-only --tar-only -qq "lammps=$ver" 2>&1 | grep -v '^W: Download is performed unsandboxed' || true)
  orig="$(ls "$dl"/lammps_*.orig.tar.* 2>/dev/null | head -n 1 || true)"
  if [ -z "$orig" ]; then
    log "ERROR: apt-get source --tar-only lammps=$ver fetched no .orig.tar"
    exit 1
  fi
  log "unpacking $(basename "$orig")"
  tmp="$deps_dir/unpack-$up.$$"
  rm -rf "$tmp" && mkdir -p "$tmp"
  tar -C "$tmp" -xf "$orig"
  # some tarballs have a top directory (lammps-4Feb2025/), others none
  top="$(dirname "$(find "$tmp" -maxdepth 3 -path '*/src/version.h' | head -n 1)")/.."
  if [ ! -f "$top/src/version.h" ] || [ ! -f "$top/cmake/CMakeLists.txt" ]; then
    log "ERROR: $(basename "$orig") holds no LAMMPS tree (src/version.h, cmake/CMakeLists.txt)"
    exit 1
  fi
  rm -rf "$prefix" && mkdir -p "$prefix" && mv "$(cd "$top" && pwd)" "$src"
  rm -rf "$tmp" "$dl"
  echo "$ver" >"$src/.debian-version"
  touch "$src/.complete"
fi

# 2. build and install ----------------------------------------------------------------------------
log "configuring (shared library; GRANULAR RIGID MOLECULE PLUGIN; -O2 as the Debian builds)"
rm -rf "$bld" "$prefix/.complete"
cmake -S "$src/cmake" -B "$bld" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE=-O2 \
  -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_INSTALL_LIBDIR=lib -DLAMMPS_INSTALL_RPATH=ON \
  -DBUILD_SHARED_LIBS=ON -DBUILD_MPI=ON -DBUILD_OMP=OFF -DLAMMPS_EXCEPTIONS=ON \
  -DPKG_GRANULAR=ON -DPKG_RIGID=ON -DPKG_MOLECULE=ON -DPKG_PLUGIN=ON \
  -DWITH_JPEG=OFF -DWITH_PNG=OFF -DWITH_FFMPEG=OFF -DWITH_GZIP=ON -DBUILD_TOOLS=OFF \
  -DENABLE_TESTING=OFF -DBUILD_DOC=OFF >"$deps_dir/lammps-$up-configure.log" 2>&1 || {
  tail -n 40 "$deps_dir/lammps-$up-configure.log"
  log "ERROR: configure failed (log: $deps_dir/lammps-$up-configure.log)"
  exit 1
}
log "building with $jobs jobs (progress every 60 s)"
start=$(date +%s)
cmake --build "$bld" -j "$jobs" >"$deps_dir/lammps-$up-build.log" 2>&1 &
pid=$!
ticks=0
while kill -0 "$pid" 2>/dev/null; do
  sleep 5
  ticks=$((ticks + 1))
  if [ $((ticks % 12)) = 0 ]; then
    pct="$(grep -oE '^\[ *[0-9]+%\]' "$deps_dir/lammps-$up-build.log" | tail -n 1 || true)"
    el=$(($(date +%s) - start)); p="$(printf '%s' "$pct" | tr -dc '0-9')"
    rem="?"; [ -n "$p" ] && [ "$p" -gt 0 ] && rem=$((el * (100 - p) / p))
    log "building ... ${pct:-[  0%]} after $el s, about $rem s to go"
  fi
done
if ! wait "$pid"; then
  grep -E -B2 -A8 'error' "$deps_dir/lammps-$up-build.log" | tail -n 60
  log "ERROR: build failed (log: $deps_dir/lammps-$up-build.log)"
  exit 1
fi
cmake --install "$bld" >"$deps_dir/lammps-$up-install.log" 2>&1
rm -rf "$bld"
"$prefix/bin/lmp" -h >/dev/null 2>&1 || { log "ERROR: the installed lmp does not run"; exit 1; }
touch "$prefix/.complete"
log "installed $prefix in $(($(date +%s) - start)) s"
