#!/usr/bin/env bash
# GFMD loading sweeps of system II at a wider bandwidth than the reference set's 256² grid
# (docs/reference-set.md, "The bandwidth set"): the adhesive cases t*q_r x gamma_s on a GRID^2
# reduced map (lambda_r/lambda_s = GRID/16), loading p* = 1e-3 .. 1e-2 (4 log-spaced loads, the
# loads the gauge of model 5 is fitted on), seeds 1..SEEDS.
#
#   scripts/bandwidth-set.sh [OUT_DIR] [GRID] [SEEDS]       (defaults: data/reference 512 3)
#
# THICKNESSES (default "inf 1 0.5 0.3 0.2 0.15 0.1") and GAMMAS (default "1 0.5 2", factors of
# the preset's gamma_s) choose the cases; JOBS (default 2) runs in parallel, each on
# RAYON_NUM_THREADS (default 1) threads. Resumable: a case whose JSON exists is skipped.
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=${1:-data/reference}
GRID=${2:-512}
SEEDS=${3:-3}
export RAYON_NUM_THREADS=${RAYON_NUM_THREADS:-1}
source scripts/gfmd-cases.sh
RUNS="$OUT/runs-bw-$GRID"
mkdir -p "$RUNS"
cases=()
for seed in $(seq 1 "$SEEDS"); do
  for f in ${GAMMAS:-1 0.5 2}; do
    for t in ${THICKNESSES:-inf 1 0.5 0.3 0.2 0.15 0.1}; do
      cases+=("system-2 $t $f $seed")
    done
  done
done
run_case() {
  local sys=$1 t=$2 f=$3 seed=$4
  gfmd_case "$RUNS/$sys-t$t-g$f-s$seed.json" "$sys t=$t gamma x$f seed $seed grid $GRID" --preset "$sys" \
    --thickness "$t" --gamma "$(python3 -c "print($G2*$f)")" --grid "$GRID" --seed "$seed" \
    --from 1e-3 --to 1e-2 --points 4
}
export RUNS G2 GRID
run_cases run_case "${cases[@]}"
