#!/usr/bin/env bash
# Thread-for-thread CPU time of Polonsky–Keer on one saved map: asperity binaries of
# `examples/pk_time.rs` (before/after builds, any number) and, when TAMAAS_PYTHON names a
# Python with tamaas, tamaas 2.9's PolonskyKeerRey (scripts/pk-vs-tamaas.py), interleaved
# round by round with the load average printed, then the minimum and median per solver.
#
#   cargo build --release --example pk_time
#   cp target/release/examples/pk_time /tmp/pk_after        # and a build of the old code
#   TAMAAS_PYTHON=venv/bin/python scripts/pk-time.sh s1024.txt 0.01 6 /tmp/pk_before /tmp/pk_after
#
# MAP is written by `asperity gfmd --preset system-1 --gamma 0 --pressure 0.01 --grid 1024
# --save-surface s1024.txt`; every solver runs on one thread (RAYON_NUM_THREADS=1,
# OMP_NUM_THREADS=1) at residual 1e-8. The CPU seconds are the solve's only (user + system).
set -euo pipefail
map=$1 pstar=$2 rounds=$3
shift 3
bins=("$@")
here=$(cd "$(dirname "$0")" && pwd)
declare -A times
for r in $(seq 1 "$rounds"); do
    load=$(cut -d' ' -f1 /proc/loadavg)
    line="round $r (load $load):"
    for b in "${bins[@]}"; do
        t=$(RAYON_NUM_THREADS=1 "$b" "$map" "$pstar" 1e-8 | sed 's/.*"solve_cpu_s": \([0-9.]*\).*/\1/')
        times[$b]="${times[$b]:-} $t"
        line="$line $(basename "$b") $t"
    done
    if [ -n "${TAMAAS_PYTHON:-}" ]; then
        t=$(OMP_NUM_THREADS=1 "$TAMAAS_PYTHON" "$here/pk-vs-tamaas.py" "$map" "$pstar" 1e-8 2>/dev/null |
            tail -1 | sed 's/.*"solve_cpu_s": \([0-9.e-]*\).*/\1/')
        times[tamaas]="${times[tamaas]:-} $t"
        line="$line tamaas $t"
    fi
    echo "$line"
done
for k in "${!times[@]}"; do
    echo "${times[$k]}" | tr ' ' '\n' | grep . | sort -g |
        awk -v k="$(basename "$k")" '{a[NR]=$1} END {printf "%s: min %.2f s, median %.2f s over %d runs\n", k, a[1], (NR % 2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2), NR}'
done
