#!/usr/bin/env bash
# Builds dgwarp's OpenFOAM motion solver, libdgwarpFoam.so (docs/OPENFOAM.md,
# "dgwarp as OpenFOAM's motion solver"), on Debian 12:
#  1. Debian's openfoam package (v1912: libraries and binaries, no headers);
#  2. its headers: the matching source package (`apt-get source openfoam`, a
#     deb-src line for bookworm added to /etc/apt/sources.list.d/ when none is
#     there), unpacked once into the cache folder, and the lnInclude folders of
#     the libraries the plugin includes (OpenFOAM's own wmakeLnInclude);
#  3. the project configured with that source (build/ by default: BUILD_DIR)
#     and the plugin built there: BUILD_DIR/openfoam/libdgwarpFoam.so;
#  4. the plugin installed into /usr/local/lib (ldconfig), so that
#     motionSolverLibs ("libdgwarpFoam.so") finds it (INSTALL=0: not installed).
# Idempotent and quiet when everything is in place.
# Cache folder: ${XDG_CACHE_HOME:-~/.cache}/dgwarp (DGWARP_OPENFOAM_CACHE), outside
# the clone, so that every clone and build folder reuses the unpacked source.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
build=${BUILD_DIR:-build}
cache=${DGWARP_OPENFOAM_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/dgwarp}
source_dir=$cache/OpenFOAM-v1912
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "build-openfoam-plugin: need root (or sudo) to install packages" >&2; exit 1; }
  sudo="sudo"
fi
quietly() {  # runs a command, printing its output only when it fails
  local log; log=$(mktemp)
  if ! "$@" >"$log" 2>&1; then cat "$log" >&2; rm -f "$log"; echo "build-openfoam-plugin: failed: $*" >&2; exit 1; fi
  rm -f "$log"
}

scripts/install-deps.sh
missing=()
for p in openfoam dpkg-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q '^install ok installed$' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "build-openfoam-plugin: installing ${missing[*]}"
  quietly $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive quietly $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

if [ ! -f "$source_dir/src/dynamicMesh/lnInclude/displacementMotionSolver.H" ]; then
  if ! grep -rqs '^Types:.*deb-src\|^deb-src ' /etc/apt/sources.list /etc/apt/sources.list.d/; then
    echo "build-openfoam-plugin: adding Debian's source packages (deb-src bookworm) to apt's sources"
    printf 'Types: deb-src\nURIs: http://deb.debian.org/debian\nSuites: bookworm\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' |
      $sudo tee /etc/apt/sources.list.d/dgwarp-openfoam-src.sources >/dev/null
    quietly $sudo apt-get update -qq
  fi
  version=$(dpkg-query -W -f='${Version}' openfoam)
  echo "build-openfoam-plugin: fetching OpenFOAM's sources (openfoam $version, 45 MB) into $cache"
  mkdir -p "$cache/download"
  (cd "$cache/download" && quietly apt-get source -qq --download-only "openfoam=${version%+b*}")
  rm -rf "$source_dir" "$source_dir.tmp"
  quietly dpkg-source -x "$cache"/download/openfoam_*.dsc "$source_dir.tmp"
  for lib in OpenFOAM OSspecific/POSIX meshTools dynamicMesh; do
    WM_PROJECT_DIR="$source_dir.tmp" quietly "$source_dir.tmp/wmake/wmakeLnInclude" -u "$source_dir.tmp/src/$lib"
  done
  # wmakeLnInclude's links are relative: the folder can move. The downloads go
  # (dpkg-source also copies the 45 MB tarball beside the tree).
  mv "$source_dir.tmp" "$source_dir"
  rm -rf "$cache/download" "$cache"/openfoam_*.orig.tar.*
fi

if [ ! -f "$build/CMakeCache.txt" ]; then
  mkdir -p "$build"
  quietly cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release "-DDGWARP_OPENFOAM_SOURCE=$source_dir"
elif ! grep -q "^DGWARP_OPENFOAM_SOURCE:PATH=$source_dir\$" "$build/CMakeCache.txt" ||
     ! grep -q "^DGWARP_FOAM_LIBOPENFOAM:FILEPATH=/" "$build/CMakeCache.txt"; then
  # Found again now that OpenFOAM and its sources are there.
  quietly cmake -S . -B "$build" "-DDGWARP_OPENFOAM_SOURCE=$source_dir" -UDGWARP_FOAM_LIB*
fi
quietly cmake --build "$build" -j "$jobs" --target dgwarpFoam dgwarp
plugin=$root/$build/openfoam/libdgwarpFoam.so
[ -f "$plugin" ] || { echo "build-openfoam-plugin: $plugin was not built" >&2; exit 1; }

if [ "${INSTALL:-1}" = 1 ] && ! cmp -s "$plugin" /usr/local/lib/libdgwarpFoam.so; then
  $sudo install -m 644 "$plugin" /usr/local/lib/libdgwarpFoam.so
  $sudo ldconfig
  echo "build-openfoam-plugin: installed /usr/local/lib/libdgwarpFoam.so"
fi
