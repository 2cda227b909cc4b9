#!/usr/bin/env bash
# GFMD at small loads and through the load cycle, with a finite-size study
# (docs/reference-set.md, "Small loads and finite size"): system II reduced as the reference set
# (lambda_r/lambda_s = 16, lambda_s/da = 8, gamma_s and rho rescaled to keep gamma_glo and the
# Tabor parameter), loads p* = 1e-5 .. 1e-2 (10 log-spaced).
#
#   scripts/small-load-set.sh [OUT_DIR] [PHASE ...]     (default: data/reference cycles finite more)
#
# Phases, in the order they are worth their CPU:
#   cycles  load cycles to pull-off on 256² maps (L/lambda_r = 2), seeds 1-3, the adhesive
#           cases at t*q_r = inf, 0.3, 0.2, 0.15 (gamma_s x 1/2, 1, 2) and the adhesionless
#           ones at inf, 0.3, 0.15
#   finite  loading sweeps on L/lambda_r = 4 (512²) and 8 (1024²) maps at the same lambda_r/lambda_s
#           and lambda_s/da, and load cycles at L/lambda_r = 4
#   more    load cycles of the remaining thicknesses (1, 0.5, 0.1)
#   large   the half-space's loading sweeps on L/lambda_r = 16 (2048²) and a second seed at 8
#           (not in the default phases)
#   seeds16 a second 2048² seed of the adhesive half-space, for a standard error at
#           L/lambda_r = 16 (not in the default phases)
# Runs are resumable (a case whose JSON exists is skipped); JOBS (default 1) run in parallel,
# each on RAYON_NUM_THREADS (default 1) threads. Each run's CPU seconds (user + system, as
# counted by the kernel) go to RUNS/cpu.log.
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=${1:-data/reference}
shift || true
PHASES=${*:-cycles finite more}
JOBS=${JOBS:-1}
export RAYON_NUM_THREADS=${RAYON_NUM_THREADS:-1}
BIN=${ASPERITY:-target/release/asperity}
[ -x "$BIN" ] || cargo build --release -q -p asperity-cli
G2=0.157  # system II's gamma_s (J/m^2)
PRESETS="$OUT/presets"
mkdir -p "$PRESETS"
# system II with the GFMD map's L/lambda_r = R at bandwidth 16 (grid = R * 16 * 8)
for r in 2 4 8 16; do
  sed -e "s/^system_size_ratio = .*/system_size_ratio = $r/" -e "s/^bandwidth = .*/bandwidth = 16/" \
    presets/system-2.toml > "$PRESETS/system-2-L$r.toml"
done
cases=()
for phase in $PHASES; do
  case $phase in
    cycles)
      for seed in 1 2 3; do
        for t in inf 0.3 0.2 0.15; do
          for f in 1 0.5 2; do cases+=("cycle 2 $t $f $seed"); done
        done
        for t in inf 0.3 0.15; do cases+=("cycle 2 $t 0 $seed"); done
      done ;;
    finite)
      for t in inf 0.3; do
        for f in 1 0; do
          cases+=("sweep 4 $t $f 1" "sweep 4 $t $f 2" "sweep 8 $t $f 1")
        done
        cases+=("cycle 4 $t 1 1")
      done ;;
    large)
      # the half-space's small-load a_r has not converged at L/lambda_r = 8: 2048² maps and a
      # second 1024² seed
      for f in 1 0; do cases+=("sweep 16 inf $f 1" "sweep 8 inf $f 2"); done ;;
    seeds16)
      cases+=("sweep 16 inf 1 2") ;;
    more)
      for seed in 1 2 3; do
        for t in 1 0.5 0.1; do
          for f in 1 0.5 2; do cases+=("cycle 2 $t $f $seed"); done
        done
      done ;;
  esac
done
run_case() {
  local kind=$1 r=$2 t=$3 f=$4 seed=$5
  local grid=$((r * 128))
  local runs="$OUT/runs-small-$kind-L$r"
  mkdir -p "$runs"
  local file="$runs/system-2-t$t-g$f-s$seed.json"
  [ -s "$file" ] && return 0
  local gamma; gamma=$(python3 -c "print($G2*$f)")
  local mode=(--from 1e-5 --to 1e-2 --points 10)
  [ "$kind" = cycle ] && mode+=(--cycle)
  local t0; t0=$(date +%s.%N)
  local times="$file.time"
  if /usr/bin/time -f "%U %S" -o "$times" "$BIN" gfmd --preset "$OUT/presets/system-2-L$r.toml" \
      --thickness "$t" --gamma "$gamma" --grid "$grid" --seed "$seed" "${mode[@]}" \
      --format json > "$file.tmp" 2> "$file.err"; then
    mv "$file.tmp" "$file"
  else
    mv "$file.tmp" "$file.failed"
  fi
  local cpu; cpu=$(awk '{print $1 + $2}' "$times"); rm -f "$times"
  echo "$kind L$r t=$t gamma x$f seed $seed grid $grid: cpu $cpu s wall $(python3 -c "import time;print(round(time.time()-$t0,1))") s" | tee -a "$runs/cpu.log" >&2
}
export -f run_case
export BIN OUT G2
printf '%s\n' "${cases[@]}" | xargs -P "$JOBS" -L 1 bash -c 'run_case $0 $1 $2 $3 $4'
