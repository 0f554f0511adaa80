#!/usr/bin/env bash
# One entry point for a new user or CI, on Debian 12 as root (or with sudo):
#   ./run.sh                 install what is missing, build, run the default scene
#   ./run.sh FILE.prm        the same, running FILE.prm
#   ./run.sh test            install what is missing, build, run the test suite
#   ./run.sh build           install what is missing and build only
set -euo pipefail
cd "$(dirname "$0")"

# libopenblas0-serial: an optimized BLAS (single-threaded, so that parallel
# runs and ctest -j do not oversubscribe) for UMFPACK's dense fronts
# python3: the size check of the sources and the reliability tests
packages=(cmake g++ make libdeal.ii-dev numdiff perl python3 openmpi-bin libopenblas0-serial)
# scripts that need more (the benchmark plots) name it here
read -r -a extra <<< "${EXTRA_PACKAGES:-}"
packages+=("${extra[@]}")
default_prm=prm/bouncing_block/mortar_stabilized.prm
jobs=$(nproc 2>/dev/null || echo 2)

install_packages() {
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" ||
      missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "== Installing Debian packages: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" > /dev/null
}

build() {
  install_packages
  echo "== Configuring and building in build/ (Release)"
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build.log 2>&1 ||
    { cat build.log; exit 1; }
  cmake --build build -j "$jobs" >> build.log 2>&1 || { tail -50 build.log; exit 1; }
  echo "   (build log: build.log)"
}

# Open MPI refuses to run as root unless told; deal.II links MPI even in serial.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1

case "${1:-}" in
  test)
    build
    echo "== Running the test suite"
    cd build
    ctest -j "$jobs" --output-on-failure
    ;;
  build)
    build
    ;;
  -h|--help)
    sed -n '2,7p' "$0"
    ;;
  *)
    prm="${1:-$default_prm}"
    build
    echo "== Running build/contact-dynamics $prm"
    build/contact-dynamics "$prm"
    ;;
esac
