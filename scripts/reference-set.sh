#!/usr/bin/env bash
# Regenerates asperity's own GFMD reference set (docs/reference-set.md): system II over
# t*q_r in {inf, 1, 0.5, 0.3, 0.2, 0.15, 0.1} x gamma_s in {0, 1/2, 1, 2} x the preset's, and
# system I at its adhesion; each a load cycle (loading p* 1e-4 -> 1e-2, unloading, tension to
# pull-off) on seeds 1..SEEDS, then the mean +- standard error over seeds.
#
#   scripts/reference-set.sh [OUT_DIR] [GRID] [SEEDS]     (defaults: data/reference 256 3)
#
# Runs are resumable: a case whose JSON exists is skipped. JOBS (default 2) runs in parallel.
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=${1:-data/reference}
GRID=${2:-256}
SEEDS=${3:-3}
source scripts/gfmd-cases.sh
RUNS="$OUT/runs-$GRID"
mkdir -p "$RUNS"
cases=()
for seed in $(seq 1 "$SEEDS"); do
  for t in inf 1 0.5 0.3 0.2 0.15 0.1; do
    for f in 1 0.5 2 0; do
      cases+=("system-2 $t $f $seed")
    done
  done
  cases+=("system-1 inf 1 $seed")
done
run_case() {
  local sys=$1 t=$2 f=$3 seed=$4
  local g0; g0=$([ "$sys" = system-2 ] && echo $G2 || echo 0.05)
  gfmd_case "$RUNS/$sys-t$t-g$f-s$seed.json" "$sys t=$t gamma x$f seed $seed" --preset "$sys" \
    --thickness "$t" --gamma "$(python3 -c "print($g0*$f)")" --grid "$GRID" --seed "$seed" \
    --cycle --from 1e-4 --to 1e-2 --points 7
}
export RUNS G2 GRID
run_cases run_case "${cases[@]}"
python3 scripts/reference-aggregate.py "$RUNS" "$OUT/reference-set-$GRID.csv" "$OUT/pull-off-$GRID.csv" \
  "$OUT/runs-$GRID.csv"
