#!/usr/bin/env bash
# smcbip check and explore on 2 and 4 MPI ranks give the answers, sample counts and verdicts of
# one process for the same seed (the timings aside), and the same exit code.
#
# Usage: mpi_ranks.sh BIN_DIR SOURCE_DIR
set -uo pipefail

bin=$1
source=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() {
  echo "mpi_ranks: $*" >&2
  exit 1
}

run() {  # run NAME RANKS COMMAND...: stdout without timings to $out/NAME, exit code to $out/NAME.code
  local name=$1 ranks=$2
  shift 2
  local launcher=()
  [[ $ranks == 1 ]] || launcher=(mpirun --oversubscribe -np "$ranks")
  timeout 300 "${launcher[@]}" "$bin/smcbip" "$@" 2>"$out/$name.err" |
    grep -v '"seconds"' >"$out/$name"
  echo "${PIPESTATUS[0]}" >"$out/$name.code"
}

channel=$source/models/channel.bip
cases=(
  "check $channel $source/models/channel.mtl --root System() --delta 0.03 --seed 7 --json"
  "explore $channel $source/models/channel_sweep.mtl --root System() --delta 0.03 --seed 8 --json"
  "check $channel $source/models/channel.mtl --root System() --method ci --delta 0.02 --json"
)
for k in "${!cases[@]}"; do
  read -r -a command <<<"${cases[$k]}"
  run "case$k-1" 1 "${command[@]}"
  grep -q '"samples"' "$out/case$k-1" || fail "case $k: no results on one process"
  for ranks in 2 4; do
    run "case$k-$ranks" "$ranks" "${command[@]}"
    if ! cmp -s "$out/case$k-1" "$out/case$k-$ranks"; then
      cat "$out/case$k-$ranks.err" >&2
      diff "$out/case$k-1" "$out/case$k-$ranks" | head -20 >&2
      fail "case $k: $ranks ranks answer otherwise than one process"
    fi
    [[ $(cat "$out/case$k-1.code") == $(cat "$out/case$k-$ranks.code") ]] ||
      fail "case $k: exit $(cat "$out/case$k-$ranks.code") on $ranks ranks, $(cat "$out/case$k-1.code") on one"
  done
done
echo "mpi_ranks: ok"
