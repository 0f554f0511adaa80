#!/usr/bin/env bash
# Reruns the reference paper's two benchmarks (bouncing block, ironing) with
# every variant, then writes the figures (doc/figures/benchmarks/*.png), the
# tables (doc/benchmarks-tables.md) and benchmarks/results/paper_benchmarks.csv.
#
# Usage: benchmarks/paper_benchmarks.sh [-j JOBS] [--only bouncing_block|ironing]
#                                       [--plots-only] [--np N]
#   -j JOBS       simulations run at the same time (default 1: wall times are
#                 then those of an idle machine; -j 2 halves the total on 2
#                 cores, but each run is slower)
#   --only NAME   run one benchmark only (the plots use what output/ holds)
#   --plots-only  run nothing, plot what output/ holds
#   --np N        run each simulation with mpirun -np N; results go to
#                 output/npN/, the figures and tables to benchmarks/results/npN/
#                 (the report in doc/ stays that of the serial runs)
# Installs what is missing (as ./run.sh does, plus python3-numpy and
# python3-matplotlib) and builds first. Each run writes output/<benchmark>_
# <variant>/ with its screen log (run.log) and run_status.txt.
set -euo pipefail
cd "$(dirname "$0")/.."

jobs=1
np=""
only=""
plots_only=0
while [ $# -gt 0 ]; do
  case "$1" in
    -j) jobs="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    --plots-only) plots_only=1; shift ;;
    --np) np="$2"; shift 2 ;;
    -h|--help) sed -n '2,18p' "$0"; exit 0 ;;
    *) echo "unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
case "$only" in ""|bouncing_block|ironing) ;;
  *) echo "--only $only: allowed are bouncing_block and ironing" >&2; exit 2 ;;
esac
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || { echo "-j $jobs: a positive integer is needed" >&2; exit 2; }
[[ -z "$np" || "$np" =~ ^[1-9][0-9]*$ ]] || { echo "--np $np: a positive integer is needed" >&2; exit 2; }
launcher=()
output_root=output
plot_options=()
if [ -n "$np" ]; then
  launcher=(mpirun -np "$np")
  output_root="output/np$np"
  plot_options=(--output-root "$output_root"
                --figures "benchmarks/results/np$np/figures"
                --tables "benchmarks/results/np$np/benchmarks-tables.md"
                --csv "benchmarks/results/np$np/paper_benchmarks.csv")
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
fi

EXTRA_PACKAGES="python3-numpy python3-matplotlib" ./run.sh build

# slowest first, so that parallel runs finish together
variants=(ironing/mortar_degree2
          ironing/nts_smoothed_friction ironing/nts_smoothed ironing/nts
          ironing/mortar_friction ironing/mortar ironing/mortar_generalized_alpha
          ironing/mortar_undamped bouncing_block/mortar_stabilized_degree2
          bouncing_block/mortar_static bouncing_block/nts
          bouncing_block/mortar_stabilized bouncing_block/mortar_generalized_alpha
          bouncing_block/mortar_undamped)
selected=()
for v in "${variants[@]}"; do
  [ -z "$only" ] || [ "${v%%/*}" = "$only" ] && selected+=("$v")
done

common=benchmarks/bench_common.py # parameter files, CSV columns by name
entry() { # file, Section/Entry -> its value
  python3 $common get "$1" "$2"
}

output_dir() { # benchmark/variant -> its output directory
  echo "$output_root/$(basename "$(entry "prm/$1.prm" "Output/Output directory")")"
}

run_one() { # benchmark/variant
  local prm="prm/$1.prm"
  local dir
  dir=$(output_dir "$1")
  rm -rf "$dir"
  mkdir -p "$dir"
  if [ "$dir" != "$(entry "$prm" "Output/Output directory")" ]; then
    python3 $common prm "$prm" "$dir/run.prm" "Output/Output directory=$dir"
    prm="$dir/run.prm"
  fi
  local start wall rc=0
  start=$(date +%s.%N)
  "${launcher[@]}" build/contact-dynamics "$prm" > "$dir/run.log" 2>&1 || rc=$?
  wall=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN {printf "%.1f", b - a}')
  local status=completed reason="reached the end time"
  if [ $rc -ne 0 ]; then
    status=stopped
    # the simulator's message, or the last lines of the log
    local log
    log=$(grep -v '^Step ' "$dir/run.log" | tr '\n' ' ' | sed 's/  */ /g')
    reason=$(echo "$log" | sed -n 's/.*Error: \(.*\)\. The run stops \(here\|at step\).*/\1/p')
    [ -n "$reason" ] || reason=$(echo "$log" | tail -c 300)
  fi
  {
    echo "status = $status"
    echo "reason = $reason"
    echo "wall_time_s = $wall"
    echo "exit_code = $rc"
    echo "jobs = $jobs"
    echo "processes = ${np:-1}"
  } > "$dir/run_status.txt"
  printf '   done %-32s %-9s %7s s  %s\n' "$1" "$status" "$wall" \
    "$([ $status = stopped ] && echo "($reason)")"
}

progress() { # one line per running variant: simulated time / end time
  local v
  for v in "$@"; do
    local prm="prm/$v.prm" dir
    dir=$(output_dir "$v")
    local t
    t=$(python3 $common last "$dir/statistics.csv" time 2>/dev/null || true)
    printf '   ... %-32s t = %s of %s\n' "$v" "${t:-0}" "$(entry "$prm" "Time integration/End time")"
  done
}

total_start=$(date +%s)
if [ $plots_only -eq 0 ]; then
  echo "== Running ${#selected[@]} simulations, $jobs at a time"
  running=()
  next_report=$(( $(date +%s) + 60 ))
  declare -A pid_of
  for v in "${selected[@]}" ""; do
    while [ ${#running[@]} -ge "$jobs" ] || { [ -z "$v" ] && [ ${#running[@]} -gt 0 ]; }; do
      sleep 5
      still=()
      for r in "${running[@]}"; do
        if kill -0 "${pid_of[$r]}" 2> /dev/null; then still+=("$r"); else wait "${pid_of[$r]}"; fi
      done
      running=("${still[@]+"${still[@]}"}")
      if [ "$(date +%s)" -ge $next_report ] && [ ${#running[@]} -gt 0 ]; then
        progress "${running[@]}"
        next_report=$(( $(date +%s) + 60 ))
      fi
    done
    [ -z "$v" ] && break
    echo "   start $v"
    run_one "$v" &
    pid_of[$v]=$!
    running+=("$v")
  done
  echo "== Simulations took $(( $(date +%s) - total_start )) s in total"
fi

echo "== Figures and tables"
python3 benchmarks/paper_benchmarks.py "${plot_options[@]}"
if [ -n "$np" ]; then
  echo "== Done in $(( $(date +%s) - total_start )) s: benchmarks/results/np$np/"
else
  echo "== Done in $(( $(date +%s) - total_start )) s: doc/figures/benchmarks/, doc/benchmarks-tables.md"
fi
