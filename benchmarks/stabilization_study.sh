#!/usr/bin/env bash
# Ironing (prm/ironing/mortar.prm, frictionless, 6 s) with the four mortar
# stabilizations (persistency, velocity persistency, velocity update, none)
# and persistency with a dissipative Newmark scheme (gamma = 0.55),
# then the figures (doc/figures/stabilization/*.png), the table
# (doc/stabilization-tables.md) and benchmarks/results/stabilization_study.csv.
#
# Usage: benchmarks/stabilization_study.sh [-j JOBS] [--end-time T]
#                                          [--refinement F] [--plots-only] [...]
#   -j JOBS         simulations at the same time (default 1; -j 2 on 2 cores
#                   halves the total, each run is slower)
#   --end-time T    shorten the runs (a test: --end-time 0.6 --refinement 0.5)
#   --refinement F  Scene/Refinement factor (default: the file's 1)
#   --plots-only    run nothing, plot what output/stabilization_* holds
#   --binary PATH   use this simulator and do not build
# Every option is passed to benchmarks/stabilization_study.py (see its --help).
# Installs what is missing (as ./run.sh does, plus python3-numpy and
# python3-matplotlib) and builds first. Each run writes
# output/stabilization_<name>/ with its screen log (run.log) and run_status.txt.
set -euo pipefail
cd "$(dirname "$0")/.."

build=1
for a in "$@"; do
  case "$a" in
    -h|--help) sed -n '2,18p' "$0"; exit 0 ;;
    --plots-only|--binary|--binary=*) build=0 ;;
  esac
done

if [ $build -eq 1 ]; then
  EXTRA_PACKAGES="python3-numpy python3-matplotlib" ./run.sh build
fi

start=$(date +%s)
python3 benchmarks/stabilization_study.py "$@"
echo "== Done in $(( $(date +%s) - start )) s: doc/figures/stabilization/, doc/stabilization-tables.md"
