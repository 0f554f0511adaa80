#!/usr/bin/env bash
# How the 3-D contact cost grows with the contact surface: the 3-D ironing
# (prm/ironing/mortar_3d.prm: the spherical tool indents the slab in 1 s
# and slides) to t = 1.1, at refinement factors F: the tool's contact
# surface (the secondary side) has round(12 F) x round(6 F) faces, the
# slab's top (60 F x 15 F) is searched for each. Reads the TimerOutput table
# of each run; one process, the linear solver SOLVER (default AMG).
# Usage: benchmarks/ironing_3d_growth.sh [F ...]   (default: 0.5 0.75 1 1.5)
# Writes benchmarks/results/ironing_3d_growth.csv and prints a Markdown
# table: the share of the wall time, and the contact cost per secondary
# face and assembly (constant: linear growth in the surface size).
set -euo pipefail
cd "$(dirname "$0")/.."
factors=("$@")
[ ${#factors[@]} -gt 0 ] || factors=(0.5 0.75 1 1.5)
solver=${SOLVER:-AMG}
exe=${BUILD_DIR:-build}/contact-dynamics
[ -x "$exe" ] || ./run.sh build
out=benchmarks/results
mkdir -p "$out"
common=benchmarks/bench_common.py # parameter files, CSV columns by name
csv="$out/ironing_3d_growth.csv"
echo "factor,secondary_faces,cells,unknowns,steps,newton_iterations,total_s,bulk_assembly_s,contact_search_s,contact_assembly_s,contact_assemblies,linear_solve_s" > "$csv"
for f in "${factors[@]}"; do
  dir="$out/ironing_3d_f$f"
  python3 $common prm prm/ironing/mortar_3d.prm "$out/ironing_3d.prm" \
    "Output/Output directory=$dir" "Output/VTU interval=0" \
    "Time integration/End time=1.1" "Nonlinear solver/Linear solver=$solver" \
    "Scene/Refinement factor=$f"
  "$exe" "$out/ironing_3d.prm" > "$dir.log"
  column() { # section, column of the timer table (3: calls, 4: seconds)
    awk -F'|' -v s="$1" -v c="$2" '{n=$2; gsub(/^ +| +$/, "", n); if (n == s) {t=$c; gsub(/[ s]/, "", t); print t}}' "$dir.log"
  }
  # (as the scene counts them: std::round(length / (0.1 / F)), halves up)
  faces=$(python3 -c "import math; h = 0.1 / $f; n = lambda l: max(1, math.floor(l / h + 0.5)); print(n(1.2) * n(0.6))")
  cells=$(sed -n "s/.*: \([0-9]*\) cells.*/\1/p" "$dir.log")
  unknowns=$(sed -n "s/.* cells, \([0-9]*\) unknowns.*/\1/p" "$dir.log")
  steps=$(sed -n 's/.*after \([0-9]*\) steps.*/\1/p' "$dir.log")
  newton=$(sed -n 's/.*steps (\([0-9]*\) Newton.*/\1/p' "$dir.log")
  total=$(sed -n 's/.*Total wallclock time elapsed since start *| *\([0-9.e+-]*\)s.*/\1/p' "$dir.log")
  echo "$f,$faces,$cells,$unknowns,$steps,$newton,$total,$(column 'bulk assembly' 4),$(column 'contact search' 4),$(column 'contact assembly' 4),$(column 'contact assembly' 3),$(column 'linear solve' 4)" >> "$csv"
done
awk -F, 'NR == 1 {print "| factor | tool faces | cells | unknowns | steps | Newton its | total (s) | contact (search + assembly) | linear solve | bulk assembly | contact per face and assembly (ms) | bulk per cell and assembly (us) |"; print "|---|---|---|---|---|---|---|---|---|---|---|---|"; next}
  {printf "| %s | %s | %s | %s | %s | %s | %.3g | %.1f %% | %.1f %% | %.1f %% | %.3g | %.3g |\n", $1, $2, $3, $4, $5, $6, $7, 100 * ($9 + $10) / $7, 100 * $12 / $7, 100 * $8 / $7, 1e3 * ($9 + $10) / ($2 * $11), 1e6 * $8 / ($3 * $11)}' "$csv"
