#!/usr/bin/env bash
# Where a step's time goes as the contact surface grows: the contact patch
# test (prm/examples/patch_test.prm) with the upper block pressed and then
# sliding by 0.05 in 10 quasi-static steps, at refinement factors F (the
# secondary surface has 7 F + 1 nodes, the volume grows as F^2). Reads the
# TimerOutput table of each run.
# Usage: benchmarks/profile_contact.sh [F ...]   (default: 1 2 4 8 16)
# Writes benchmarks/results/profile_contact.csv and prints a Markdown table.
set -euo pipefail
cd "$(dirname "$0")/.."
factors=("$@")
[ ${#factors[@]} -gt 0 ] || factors=(1 2 4 8 16)
exe=${BUILD_DIR:-build}/contact-dynamics
[ -x "$exe" ] || ./run.sh build
out=benchmarks/results
mkdir -p "$out"
common=benchmarks/bench_common.py # parameter files, CSV columns by name
csv="$out/profile_contact.csv"
sections=("bulk assembly" "contact search" "contact assembly" "linear solve" "output")
echo "factor,secondary_nodes,cells,newton_iterations,total_s,bulk_assembly_s,contact_search_s,contact_assembly_s,linear_solve_s,output_s" > "$csv"
for f in "${factors[@]}"; do
  dir="$out/profile_f$f"
  python3 $common prm prm/examples/patch_test.prm "$out/profile.prm" \
    "Output/Output directory=$dir" "Output/VTU interval=0" "Time integration/Time step=0.1" \
    "Boundary conditions/Dirichlet=lower_bottom: xy: 0; upper_top: y: -1e-3*min(10*t, 1); upper_top: x: 0.05*t" \
    "Scene/Refinement factor=$f"
  "$exe" "$out/profile.prm" > "$dir.log"
  time_of() { # section -> seconds
    awk -F'|' -v s="$1" '{n=$2; gsub(/^ +| +$/, "", n); if (n == s) {t=$4; gsub(/[ s]/, "", t); print t}}' "$dir.log"
  }
  cells=$(sed -n "s/.*: \([0-9]*\) cells.*/\1/p" "$dir.log")
  newton=$(python3 $common last "$dir/statistics.csv" cumulative_newton_iterations)
  total=$(sed -n 's/.*Total wallclock time elapsed since start *| *\([0-9.e+-]*\)s.*/\1/p' "$dir.log")
  row="$f,$((7 * f + 1)),$cells,$newton,$total"
  for s in "${sections[@]}"; do row="$row,$(time_of "$s")"; done
  echo "$row" >> "$csv"
done
awk -F, 'NR == 1 {print "| factor | secondary nodes | cells | Newton iterations | total (s) | bulk assembly | contact search | contact assembly | linear solve | output | contact (search + assembly) per node and iteration (us) |"; print "|---|---|---|---|---|---|---|---|---|---|---|"; next}
  {printf "| %s | %s | %s | %s | %.3g | %.3g | %.3g | %.3g | %.3g | %.3g | %.3g |\n", $1, $2, $3, $4, $5, $6, $7, $8, $9, $10, 1e6 * ($7 + $8) / ($2 * $4)}' "$csv"
