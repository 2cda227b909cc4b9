# Sourced from the repository root by the scripts that build GFMD reference data
# (reference-set.sh, bandwidth-set.sh): the binary (ASPERITY, else a release build), one case
# of `asperity gfmd` run into its JSON file, and the cases run JOBS at a time; G2, system II's
# gamma_s, which the scripts' gamma factors multiply.
BIN=${ASPERITY:-target/release/asperity}
[ -x "$BIN" ] || cargo build --release -q -p asperity-cli
JOBS=${JOBS:-2}
G2=0.157  # system II's gamma_s (J/m^2)

# gfmd_case FILE LABEL ARGS...: `$BIN gfmd ARGS... --format json` into FILE, skipped where FILE
# exists and is not empty (the runs are resumable); a failed run's output goes to FILE.failed,
# its stderr to FILE.err; then "LABEL: <wall seconds> s" on stderr.
gfmd_case() {
  local file=$1 label=$2
  shift 2
  [ -s "$file" ] && return 0
  local t0; t0=$(date +%s.%N)
  if "$BIN" gfmd "$@" --format json > "$file.tmp" 2> "$file.err"; then
    mv "$file.tmp" "$file"
  else
    mv "$file.tmp" "$file.failed"
  fi
  echo "$label: $(python3 -c "import time;print(round(time.time()-$t0,1))") s" >&2
}

# run_cases FUNCTION CASE...: FUNCTION on each case's words, JOBS at a time (FUNCTION and the
# variables it reads exported).
run_cases() {
  local f=$1
  shift
  export -f gfmd_case "$f"
  export BIN
  printf '%s\n' "$@" | xargs -P "$JOBS" -L 1 bash -c "$f"' "$@"' _
}
