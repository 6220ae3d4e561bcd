#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# tdem set-up: installs the Debian packages tdem needs, fetches the LAMMPS headers from
# Debian's own source package, and builds. Idempotent: a second run only rebuilds what changed.
#
#   bash tools/setup.sh            (as root on Debian 12; uses sudo if not root)
#
# Environment: TDEM_BUILD_DIR (default build/), TDEM_DEPS_DIR (default /var/cache/tdem),
#              TDEM_JOBS (default: number of cores).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${TDEM_BUILD_DIR:-$here/build}"
deps_dir="${TDEM_DEPS_DIR:-/var/cache/tdem}"
jobs="${TDEM_JOBS:-$(nproc)}"

SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive

log() { printf '[tdem setup] %s\n' "$*"; }

packages=(
  liggghts libliggghts-dev liggghts-doc
  lammps liblammps-dev lammps-examples
  libopenmpi-dev openmpi-bin
  cmake g++ make
  googletest libgtest-dev libbenchmark-dev
  python3 python3-matplotlib python3-numpy
  dpkg-dev xz-utils ca-certificates
)

# 1. Debian packages --------------------------------------------------------------------------
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
updated=0
if [ "${#missing[@]}" -gt 0 ]; then
  log "installing: ${missing[*]}"
  $SUDO apt-get update -qq
  updated=1
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# 2. LAMMPS headers from Debian's source package ---------------------------------------------
# liblammps-dev ships only a few headers; the styles need the full set of the same version.
lmp_version="$(dpkg-query -W -f='${Version}' liblammps-dev)"
lmp_upstream="${lmp_version%-*}"          # strip the Debian revision
lmp_upstream="${lmp_upstream#*:}"         # strip an epoch
lmp_tree="$deps_dir/lammps-$lmp_upstream"
if [ ! -f "$lmp_tree/.complete" ]; then
  src_list=/etc/apt/sources.list.d/tdem-debian-src.sources
  if ! grep -rqs "^Types:.*deb-src" /etc/apt/sources.list.d/ && ! grep -qs "^deb-src" /etc/apt/sources.list; then
    log "enabling a deb-src entry for Debian's archive ($src_list)"
    $SUDO tee "$src_list" >/dev/null <<'EOF'
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm bookworm-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
EOF
    updated=0
  fi
  [ "$updated" = 1 ] || $SUDO apt-get update -qq
  $SUDO mkdir -p "$deps_dir/download"
  log "fetching the LAMMPS source package $lmp_version (headers only are unpacked)"
  (cd "$deps_dir/download" && $SUDO apt-get source --download-only -qq "lammps=$lmp_version" >/dev/null 2>&1 ||
     $SUDO apt-get source --download-only -qq lammps >/dev/null)
  orig="$(ls "$deps_dir"/download/lammps_*.orig.tar.* | head -n 1)"
  tmp="$deps_dir/unpack.$$"
  $SUDO rm -rf "$tmp" && $SUDO mkdir -p "$tmp"
  $SUDO tar -C "$tmp" -xf "$orig" --wildcards --no-wildcards-match-slash \
    '*/src/*.h' '*/src/fmt/*' '*/src/GRANULAR/*' '*/src/PLUGIN/*' '*/src/main.cpp' \
    '*/bench/in.chute*' '*/bench/data.chute' '*/examples/pour/*' '*/examples/granregion/*' \
    '*/examples/granular/*'
  $SUDO rm -rf "$lmp_tree"
  $SUDO mv "$tmp"/lammps-* "$lmp_tree"
  $SUDO rm -rf "$tmp" "$deps_dir/download"
  $SUDO touch "$lmp_tree/.complete"
fi

# 3. Build ------------------------------------------------------------------------------------
cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DTDEM_LAMMPS_SOURCE="$lmp_tree" >/dev/null
if ! cmake --build "$build_dir" -j "$jobs" >"$build_dir/build.log" 2>&1; then
  grep -E -B2 -A6 'error|Error' "$build_dir/build.log" | tail -n 80
  log "build failed (full log: $build_dir/build.log)"
  exit 1
fi
log "built in $build_dir"
