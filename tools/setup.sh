#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# tdem set-up: installs the Debian packages tdem needs, fetches the headers of the packaged
# LAMMPS from Debian's own source package, optionally builds further LAMMPS releases from their
# Debian source packages, and builds tdem. Idempotent: a second run only rebuilds what changed.
#
#   bash tools/setup.sh [--lammps "UPSTREAM ..."]     (as root on Debian 12 or 13; sudo otherwise)
#
#   --lammps "20250204 20260704"   also build these LAMMPS releases from source (cached under
#                                  /var/cache/tdem/lammps-UPSTREAM, tools/lammps_from_source.sh)
#                                  and build tdem against them; a release that is the packaged
#                                  LAMMPS of this Debian is taken from the package instead.
# Environment: TDEM_BUILD_DIR (default build/), TDEM_DEPS_DIR (default /var/cache/tdem),
#              TDEM_JOBS (default: number of cores).
#
# The Debian release and the package mirror come from this machine: the codename from
# /etc/os-release, the mirror from the apt sources it already uses (apt-get indextargets).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${TDEM_BUILD_DIR:-$here/build}"
deps_dir="${TDEM_DEPS_DIR:-/var/cache/tdem}"
jobs="${TDEM_JOBS:-$(nproc)}"
want_lammps=""
while [ $# -gt 0 ]; do
  case "$1" in
    --lammps) want_lammps="${2:-}"; shift 2 ;;
    *) echo "setup.sh: unknown option '$1' (allowed: --lammps \"UPSTREAM ...\")" >&2; exit 2 ;;
  esac
done

SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive

log() { printf '[tdem setup] %s\n' "$*"; }
t0=$(date +%s)

packages=(
  liggghts libliggghts-dev liggghts-doc
  lammps liblammps-dev lammps-examples
  libopenmpi-dev openmpi-bin
  cmake g++ make
  libvtk9-dev python3-vtk9 xvfb xauth
  googletest libgtest-dev libbenchmark-dev
  python3 python3-matplotlib python3-numpy
  dpkg-dev xz-utils ca-certificates debian-archive-keyring
)

# 1. Debian packages --------------------------------------------------------------------------
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  log "installing: ${missing[*]}"
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# 2. deb-src entries for the source packages ----------------------------------------------------
# This Debian's own suite (the packaged LAMMPS) and, when further releases are wanted, the
# suites that carry them (trixie: 4Feb2025, forky: 4Jul2026). Only suites that have no deb-src
# entry yet are added, on the mirror this machine already uses for its own suite.
codename="$(. /etc/os-release && echo "${VERSION_CODENAME:-}")"
if [ -z "$codename" ]; then
  log "ERROR: /etc/os-release names no VERSION_CODENAME; tdem's set-up needs Debian 12 or 13"
  exit 1
fi
suites=("$codename")
[ -z "$want_lammps" ] || suites+=(trixie forky)
have_src="$(apt-get indextargets --format '$(RELEASE)' 'Created-By: Sources' 2>/dev/null | sort -u)"
add=()
for s in "${suites[@]}"; do
  grep -qx "$s" <<<"$have_src" || { [[ " ${add[*]-} " == *" $s "* ]] || add+=("$s"); }
done
if [ "${#add[@]}" -gt 0 ]; then
  mirror="$(apt-get indextargets --format '$(SITE) $(RELEASE)' 'Created-By: Packages' 2>/dev/null |
            awk -v c="$codename" '$2 == c {print $1; exit}')"
  if [ -z "$mirror" ]; then
    log "ERROR: no apt source of this machine serves the suite '$codename', so there is no mirror to"
    log "       take Debian's source packages from; add a deb (or deb-src) entry for '$codename'"
    exit 1
  fi
  src_list=/etc/apt/sources.list.d/tdem-debian-src.sources
  log "enabling deb-src for ${add[*]} on $mirror ($src_list)"
  {
    if [ -f "$src_list" ]; then cat "$src_list"; echo; fi
    printf 'Types: deb-src\nURIs: %s\nSuites: %s\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
      "$mirror" "${add[*]}"
  } >"/tmp/tdem-src.$$"
  $SUDO install -m 0644 "/tmp/tdem-src.$$" "$src_list"
  rm -f "/tmp/tdem-src.$$"
  $SUDO apt-get update -qq
fi

# 3. headers of the packaged LAMMPS from Debian's source package ------------------------------
# liblammps-dev ships only a few headers; the styles need the full set of the same version.
lmp_srcver="$(dpkg-query -W -f='${source:Version}' liblammps-dev)"   # source version, no +bN
lmp_upstream="$(dpkg-query -W -f='${source:Upstream-Version}' liblammps-dev)"
lmp_tree="$deps_dir/debian-lammps-$lmp_upstream"
# (fix_neigh_history.cpp: tdem's build reads how it stores history partner IDs in restart files)
if [ ! -f "$lmp_tree/.complete" ] || [ ! -f "$lmp_tree/src/fix_neigh_history.cpp" ]; then
  $SUDO mkdir -p "$deps_dir/download"
  log "fetching the LAMMPS source package $lmp_srcver (headers only are unpacked)"
  (cd "$deps_dir/download" && $SUDO apt-get source --download-only --tar-only -qq "lammps=$lmp_srcver" 2>&1 |
     grep -v '^W: Download is performed unsandboxed' || true)
  orig="$(ls "$deps_dir"/download/lammps_*.orig.tar.* 2>/dev/null | head -n 1 || true)"
  if [ -z "$orig" ]; then
    log "ERROR: apt-get source --tar-only lammps=$lmp_srcver fetched nothing (is deb-src for '$codename' reachable?)"
    exit 1
  fi
  tmp="$deps_dir/unpack.$$"
  $SUDO rm -rf "$tmp" && $SUDO mkdir -p "$tmp"
  # the tarball's top directory, if it has one (lammps-4Feb2025/ ...; some have none)
  first="$(tar -tf "$orig" 2>/dev/null | head -n 1 || true)"
  p=""
  [[ "$first" == */* ]] && p="${first%%/*}/"
  $SUDO tar -C "$tmp" -xf "$orig" --wildcards --no-wildcards-match-slash \
    "${p}src/*.h" "${p}src/fmt/*" "${p}src/GRANULAR/*" "${p}src/PLUGIN/*" "${p}src/main.cpp" \
    "${p}src/fix_neigh_history.cpp" \
    "${p}bench/in.chute*" "${p}bench/data.chute" "${p}examples/pour/*" "${p}examples/granregion/*" \
    "${p}examples/granular/*"
  top="$(dirname "$(find "$tmp" -maxdepth 3 -path '*/src/version.h' | head -n 1)")/.."
  $SUDO rm -rf "$lmp_tree"
  $SUDO mv "$(cd "$top" && pwd)" "$lmp_tree"
  $SUDO rm -rf "$tmp" "$deps_dir/download"
  $SUDO touch "$lmp_tree/.complete"
fi

# 4. further LAMMPS releases, built from source -------------------------------------------------
extra=()
vname() { grep -h 'define LAMMPS_VERSION ' "$1/version.h" | sed 's/.*"\(.*\)".*/\1/' | tr -d ' '; }
require="$(vname "$lmp_tree/src")"
for up in $want_lammps; do
  if [[ "$lmp_upstream" == "$up"* ]]; then
    log "LAMMPS $up is this Debian's package: taken from the package"
    continue
  fi
  bash "$here/tools/lammps_from_source.sh" "$up"
  require="$require;$(vname "$deps_dir/lammps-$up/source/src")"
done
# every LAMMPS built here before is built against too (so the showcase and the tests configure alike)
for d in "$deps_dir"/lammps-*/; do
  d="${d%/}"
  [ -f "$d/.complete" ] && [ -f "$d/source/src/pair.h" ] || continue
  [[ "$(basename "$d")" == lammps-"$lmp_upstream"* ]] && continue
  extra+=("$d")
done
extra_list="$(IFS=';'; echo "${extra[*]-}")"

# 5. Build ------------------------------------------------------------------------------------
mkdir -p "$build_dir"
if ! cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DLAMMPS_HEADER_DIR="$lmp_tree/src" \
      -DTDEM_LAMMPS_EXTRA="$extra_list" -DTDEM_REQUIRE_LAMMPS="$require" >"$build_dir/configure.log" 2>&1; then
  tail -n 40 "$build_dir/configure.log"
  log "configure failed (full log: $build_dir/configure.log)"
  exit 1
fi
grep -E '^-- tdem LAMMPS [0-9]' "$build_dir/configure.log" | sed 's/^-- /[tdem setup] /' || true
log "building tdem ($jobs jobs; progress every 60 s)"
tb=$(date +%s)
cmake --build "$build_dir" -j "$jobs" >"$build_dir/build.log" 2>&1 &
bpid=$!
ticks=0
while kill -0 "$bpid" 2>/dev/null; do
  sleep 5
  ticks=$((ticks + 1))
  if [ $((ticks % 12)) = 0 ]; then
    pct="$(grep -oE '^\[ *[0-9]+%\]' "$build_dir/build.log" | tail -n 1 || true)"
    el=$(($(date +%s) - tb)); p="$(printf '%s' "$pct" | tr -dc '0-9')"
    rem="?"; [ -n "$p" ] && [ "$p" -gt 0 ] && rem=$((el * (100 - p) / p))
    log "building tdem ... ${pct:-[  0%]} after $el s, about $rem s to go"
  fi
done
if ! wait "$bpid"; then
  grep -E -B2 -A6 'error|Error' "$build_dir/build.log" | tail -n 80
  log "build failed (full log: $build_dir/build.log)"
  exit 1
fi
if grep -q 'warning:' "$build_dir/build.log"; then
  log "the build printed $(grep -c 'warning:' "$build_dir/build.log") warning(s) (see $build_dir/build.log)"
fi
log "built in $build_dir ($(($(date +%s) - t0)) s of set-up)"
