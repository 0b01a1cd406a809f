#!/usr/bin/env bash
# Times `bipc check` on generated chain, chain-with-priorities and broadcast models of 10 to 10,000 atoms.
#
# Usage: bench/frontend_scaling.sh [BUILD_DIR]   (default: build)
# Prints, per family and size, the best wall time of a few runs, the peak resident memory, the
# ratio to the size ten times smaller (about 10 when growth is linear; small sizes are dominated
# by process start-up) and the time per atom. Fails when a 10,000-atom model takes 1 s or more.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
build_dir=${1:-build}
bipc="$build_dir/bin/bipc"
generator="$build_dir/bin/gen_bip_models"
models_dir="$build_dir/bench-models"
sizes=(10 100 1000 10000)
runs=3
limit_seconds=1.0
max_step_ratio=20

for tool in "$bipc" "$generator"; do
  if [[ ! -x "$tool" ]]; then
    echo "frontend_scaling: $tool not found; build first (make build)" >&2
    exit 2
  fi
done
if [[ ! -x /usr/bin/time ]]; then
  echo "frontend_scaling: /usr/bin/time not found; run scripts/install-deps.sh" >&2
  exit 2
fi
mkdir -p "$models_dir"

# Runs bipc check on $1 once; prints "seconds peak_rss_kb". Fails with bipc's output on error.
time_check() {
  local model=$1 report start end
  report=$(mktemp)
  start=$EPOCHREALTIME
  if ! /usr/bin/time -v -o "$report" "$bipc" check "$model" --root 'Top()' >/dev/null 2>"$report.err"; then
    echo "frontend_scaling: bipc check failed on $model:" >&2
    head -n 20 "$report.err" >&2
    rm -f "$report" "$report.err"
    return 1
  fi
  end=$EPOCHREALTIME
  local rss
  rss=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$report")
  rm -f "$report" "$report.err"
  awk -v s="$start" -v e="$end" -v r="$rss" 'BEGIN { printf "%.6f %d\n", e - s, r }'
}

status=0
printf '%-10s %7s %10s %9s %12s %10s\n' family atoms seconds peak_MB 'x_prev(10x)' 'us/atom'
for family in chain priorities broadcast; do
  previous=""
  for n in "${sizes[@]}"; do
    model="$models_dir/${family}_$n.bip"
    "$generator" --family "$family" --atoms "$n" -o "$model"
    best="" peak=0
    for ((run = 0; run < runs; run++)); do
      read -r seconds rss < <(time_check "$model") || exit 1
      if [[ -z "$best" ]] || awk -v a="$seconds" -v b="$best" 'BEGIN { exit !(a < b) }'; then
        best=$seconds
      fi
      if ((rss > peak)); then peak=$rss; fi
    done
    ratio="-"
    if [[ -n "$previous" ]]; then
      ratio=$(awk -v a="$best" -v b="$previous" 'BEGIN { printf "%.2f", (b > 0 ? a / b : 0) }')
    fi
    awk -v f="$family" -v n="$n" -v s="$best" -v m="$peak" -v r="$ratio" 'BEGIN {
      printf "%-10s %7d %10.4f %9.1f %12s %10.2f\n", f, n, s, m / 1024, r, s * 1e6 / n }'
    if ((n == 10000)) && awk -v s="$best" -v l="$limit_seconds" 'BEGIN { exit !(s >= l) }'; then
      echo "frontend_scaling: FAIL: $family with $n atoms took ${best}s (limit ${limit_seconds}s)" >&2
      status=1
    fi
    # Linear growth means about 10x per step; start-up time dominates below 1000 atoms, so only
    # the last step is judged, with room for timing noise.
    if ((n == 10000)) && awk -v r="$ratio" -v l="$max_step_ratio" 'BEGIN { exit !(r >= l) }'; then
      echo "frontend_scaling: FAIL: $family grows superlinearly: x${ratio} from 1000 to $n atoms" >&2
      status=1
    fi
    previous=$best
  done
done
exit "$status"
