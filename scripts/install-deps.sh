#!/usr/bin/env bash
# Installs the Debian packages this project needs, only those missing. Idempotent.
#   install-deps.sh            build and test (openmpi: the rank-equality tests of verification/mpi)
#   install-deps.sh --report   also what the nightly tier needs: chromium (renders the V&V report),
#                              paraview, python3-paraview and xvfb (pvpython opens and draws the dam break,
#                              validation/paraview), clang with libFuzzer and its OpenMP headers (the fuzz
#                              tier's scene-reader target, fuzz/CMakeLists.txt), slurm-wlm and munge (the
#                              single-node Slurm cluster of validation/matrix/single_node_slurm.py)
set -euo pipefail
packages=(g++ cmake make pkg-config libgtest-dev libeigen3-dev libhdf5-dev libgsl-dev libtomlplusplus-dev
  libcli11-dev libbenchmark-dev python3-numpy python3-h5py python3-matplotlib python3-pytest openmpi-bin libopenmpi-dev)
[ "${1:-}" = "--report" ] && packages+=(chromium paraview python3-paraview xvfb clang libclang-rt-14-dev libomp-14-dev
  slurm-wlm munge)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "installing: ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
$sudo apt-get -o DPkg::Lock::Timeout=900 update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get -o DPkg::Lock::Timeout=900 install -y -qq --no-install-recommends "${missing[@]}"
