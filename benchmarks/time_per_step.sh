#!/usr/bin/env bash
# Time per step of a scene, median of repeated runs, with and without VTU
# output. Usage: benchmarks/time_per_step.sh [FILE.prm] [REPEATS] [Entry=value ...]
# where each Entry=value changes an entry, named Section/Entry or, for every
# section of FILE.prm that sets it, Entry alone (for example
# Jacobian=approximate); FILE.prm is included, not edited. Writes
# benchmarks/results/time_per_step.csv and prints a Markdown table row.
set -euo pipefail
cd "$(dirname "$0")/.."
prm="${1:-prm/bouncing_block/no_contact.prm}"
repeats="${2:-5}"
shift $(( $# > 2 ? 2 : $# ))
[ -x build/contact-dynamics ] || ./run.sh build
common=benchmarks/bench_common.py # parameter files, CSV columns by name
out=benchmarks/results
mkdir -p "$out"
csv="$out/time_per_step.csv"
echo "variant,repeat,steps,newton_iterations,wall_time_s,time_per_step_ms" > "$csv"

run_variant() { # name, vtu interval, Entry=value ...
  local name=$1 vtu=$2
  shift 2
  for r in $(seq 1 "$repeats"); do
    local dir="$out/run_${name}_$r"
    python3 $common prm "$prm" "$out/run.prm" "Output/Output directory=$dir" \
      "Output/VTU interval=$vtu" "$@"
    build/contact-dynamics "$out/run.prm" > "$out/run_${name}_$r.log"
    python3 $common last "$dir/statistics.csv" step cumulative_newton_iterations wall_time |
      awk -F, -v n="$name" -v r="$r" \
      '{printf "%s,%d,%d,%d,%.4f,%.3f\n", n, r, $1, $2, $3, 1000*$3/$1}' >> "$csv"
  done
}
run_variant no_vtu 0 "$@"
run_variant vtu_every_4 4 "$@"

median() { # variant -> median time per step in ms
  grep "^$1," "$csv" | cut -d, -f6 | sort -g |
    awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'
}
m0=$(median no_vtu); m4=$(median vtu_every_4)
steps=$(grep "^no_vtu," "$csv" | head -1 | cut -d, -f3)
its=$(grep "^no_vtu," "$csv" | head -1 | cut -d, -f4)
echo "| scene file | steps | Newton iterations | median ms/step, no VTU | median ms/step, VTU every 4 steps | ratio |"
echo "|---|---|---|---|---|---|"
label="$prm${*:+ ($*)}"
awk -v p="$label" -v s="$steps" -v i="$its" -v a="$m0" -v b="$m4" \
  'BEGIN {printf "| %s | %d | %d | %.2f | %.2f | %.2f |\n", p, s, i, a, b, b/a}'
