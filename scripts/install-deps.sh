#!/usr/bin/env bash
# Installs the Debian 12 packages dgwarp needs to build, test and run.
# Open MPI (libopenmpi-dev, openmpi-bin): the dgwarp_mpi library, `mpirun dgwarp`
# and the MPI tests (docs/MPI.md); without it they are skipped. strace: the MPI
# test that each process opens only its own processor folder of an OpenFOAM case.
# python3-venv, python3-pip, python3-setuptools, python3-wheel: `pip install .`
# of the Python package (docs/PYTHON.md) and its test. python3-mpi4py: its
# prepare(comm=...).
# libsuitesparse-dev: CHOLMOD, the laplacian method's 3D factorisation;
# libopenblas0-serial: its dense blocks (3.5 x the reference BLAS; serial, so
# results do not depend on a BLAS thread count).
# ccache: a fresh clone on a machine that has built dgwarp compiles only what
# changed (CMakeLists.txt, DGWARP_CCACHE).
# Idempotent: prints nothing and touches nothing when everything is present.
# `install-deps.sh fuzz` also installs what scripts/fuzz.sh needs (clang,
# libFuzzer and the sanitizer runtimes, LLVM's OpenMP).
set -euo pipefail

packages=(
  build-essential cmake ccache pkg-config python3 python3-jsonschema
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libeigen3-dev libmetis-dev libsuitesparse-dev libopenblas0-serial libnanoflann-dev libcli11-dev nlohmann-json3-dev
  libgmsh-dev libcairo2-dev zlib1g-dev python3-meshio
  libcgns-dev cgns-convert
  python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest python3-matplotlib
  python3-venv python3-pip python3-setuptools python3-wheel python3-mpi4py
  libgtest-dev libbenchmark-dev
  libopenmpi-dev openmpi-bin strace
)
if [ "${1:-}" = fuzz ]; then
  packages+=(clang libclang-rt-14-dev libomp-dev)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q '^install ok installed$'; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "dgwarp: installing missing packages: ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "dgwarp: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
log=$(mktemp)
if ! { $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"; } >"$log" 2>&1; then
  cat "$log" >&2
  rm -f "$log"
  echo "dgwarp: package installation failed" >&2
  exit 1
fi
rm -f "$log"
echo "dgwarp: packages installed"
