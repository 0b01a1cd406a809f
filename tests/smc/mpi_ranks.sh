#!/usr/bin/env bash
# smcbip check and explore on 2 and 4 MPI ranks give the answers, sample counts and verdicts of
# one process for the same seed (the timings aside), and the same exit code. Then a rank killed
# during a job: rank 0 still reports the queries answered before, says which query the end of
# the job interrupted, and writes its CSV whole.
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

# A quick SPRT (a second at most), then an estimate of 1.8 million runs (a minute at least)
# that the kill interrupts after 8 s. The launcher gives rank 0 5 s between SIGTERM and SIGKILL
# to report (its default, 1 s, is short on a loaded machine).
printf 'const c = 7\nP>=0.5 [ F[0,26] (serverC.sc == c && serverM.sm == c) ]\n%s\n' \
  'P=? [ F[0,26] (serverC.sc == c && serverM.sm == c) ]' >"$out/two.mtl"
OMPI_MCA_odls_base_sigkill_timeout=5 timeout 120 mpirun --oversubscribe -np 3 \
  "$bin/smcbip" explore "$source/models/tandem.bip" "$out/two.mtl" --root 'System()' \
  --delta 0.001 --csv "$out/answers.csv" \
  >"$out/stdout" 2>"$out/stderr" &
launcher=$!
sleep 8
killed=""
for pid in $(pgrep -f "$bin/smcbip explore"); do
  rank=$(tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | sed -n 's/^OMPI_COMM_WORLD_RANK=//p')
  if [[ $rank == 2 ]]; then
    kill -9 "$pid" && killed=$pid
  fi
done
[[ -n $killed ]] || fail "killed rank: no rank 2 to kill"
wait "$launcher"
code=$?
[[ $code != 0 && $code != 124 ]] || fail "killed rank: exit $code after a rank was killed"
grep -q "does not hold  [0-9]* runs" "$out/stdout" ||
  fail "killed rank: the first query's answer is missing: $(cat "$out/stdout" "$out/stderr")"
grep -q "no answer: the MPI job was ended" "$out/stdout" ||
  fail "killed rank: the interrupted query is not reported: $(cat "$out/stdout")"
grep -q "two.mtl:3:1: error: .*the MPI job was ended" "$out/stderr" ||
  fail "killed rank: no error at the query's line on stderr: $(cat "$out/stderr")"
[[ $(wc -l <"$out/answers.csv") == 3 ]] || fail "killed rank: the CSV is not whole: $(cat "$out/answers.csv")"
ls "$out" | grep -q tmp && fail "killed rank: a temporary file was left: $(ls "$out")"
echo "mpi_ranks: ok"
