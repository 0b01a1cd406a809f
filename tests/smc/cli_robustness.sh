#!/usr/bin/env bash
# The command-line layer of bipc and smcbip on hostile input: numbers out of range or not finite,
# thread counts that would exhaust the machine, output files that are links, FIFOs, devices or
# folders, a --save-traces folder already used, and what every tool answers to --version and
# --help. Each case checks the exit code and the message, and that nothing was written.
#
# Usage: cli_robustness.sh BIN_DIR SOURCE_DIR
set -uo pipefail

bin=$1
source=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
failures=0
cases=0
channel=$source/models/channel.bip
rendezvous=$source/models/families/rendezvous_10.bip

fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# expect CODE PHRASE COMMAND...: the command exits with CODE within 60 s and its stderr holds
# PHRASE (empty: anything).
expect() {
  cases=$((cases + 1))
  local code=$1 phrase=$2
  shift 2
  timeout 60 "$@" >"$out/stdout" 2>"$out/stderr" </dev/null
  local actual=$?
  if [[ $actual -ne $code ]]; then
    fail "$* exited with $actual, not $code: $(head -c 300 "$out/stderr")"
  elif [[ -n $phrase ]] && ! grep -qF -- "$phrase" "$out/stderr"; then
    fail "$*: stderr lacks '$phrase': $(head -c 300 "$out/stderr")"
  fi
}

printf 'P=? [ F[0,100] Channel.lost > 0 ]\n' >"$out/one.mtl"
printf 'P>=0.5 [ G[0,1] Channel.lost >= 0 ]\n' >"$out/holds.mtl"
printf 'param t = 0:100:50\nP=? [ F[0,t] Channel.lost > 0 ]\n' >"$out/sweep.mtl"
base=("$bin/smcbip" check "$channel" "$out/one.mtl" --root 'System()')
checking=("${base[@]}" --threads 2)
check=("${checking[@]}" --delta 0.1)
simulating=("$bin/smcbip" simulate "$rendezvous" --root 'Top()')
simulate=("${simulating[@]}" --limit 3)

# --- numbers: NaN and infinities, negative or oversized integers
for option in --delta --alpha --beta --confidence; do
  for value in nan -nan inf -inf NaN; do
    expect 2 "$option: '$value' is not a finite number" "${checking[@]}" "$option" "$value"
  done
done
expect 2 "--delta: '0.7' is not in" "${checking[@]}" --delta 0.7
expect 2 "--seed: '-1' is not an integer" "${check[@]}" --seed -1
expect 2 "--seed: '18446744073709551616' is not an integer" "${check[@]}" \
  --seed 18446744073709551616
expect 0 "" "${check[@]}" --seed 18446744073709551615
expect 64 "--seed: '-1' is not an integer" "${simulate[@]}" --seed -1
expect 64 "--seed: '0x10' is not an integer" "${simulate[@]}" --seed 0x10
expect 64 "--run-index: '-1' is not an integer" "${simulate[@]}" --seed 1 --run-index -1
expect 64 "--limit: '0' is not an integer" "${simulating[@]}" --limit 0
expect 64 "--unbounded-mean: 'nan' is not a finite number" "${simulate[@]}" --unbounded-mean nan
expect 2 "--max-steps: '-1' is not an integer" "${check[@]}" --max-steps -1

# --- a parameter's range cannot list more values than memory holds
expect 2 "gives more than 100000 values" "${check[@]/$out\/one.mtl/$out/sweep.mtl}" \
  --param 't=0:1e12:1'
expect 2 "the range's numbers must be finite" "${check[@]/$out\/one.mtl/$out/sweep.mtl}" \
  --param 't=0:inf:1'

# --- threads: bounded, with a clear error instead of starting them
expect 2 "--threads: '100000' is not a number of threads" "${base[@]}" --threads 100000
expect 2 "--threads: '0' is not a number of threads" "${base[@]}" --threads 0
expect 64 "--threads: '100000' is not a number of threads" "${simulate[@]}" \
  --engine multithread --threads 100000
expect 0 "" "${simulate[@]}" --engine multithread --threads 2 --seed 1
expect 64 "--engine: 'bogus' is not one of multithread, optimised, optimized, reference" \
  "${simulate[@]}" --engine bogus
expect 64 "--trace: 'xml' is not one of jsonl, text" "${simulate[@]}" --trace xml
expect 0 "" "${simulate[@]}" --engine OPTIMISED --trace JSONL --seed 1

# --- --explore keeps a bounded number of states (it grew without end on an infinite space)
expect 0 "" "${simulating[@]}" --explore --max-states 1000
grep -qF "exploration cut at 1000 states (--max-states)" "$out/stdout" ||
  fail "--explore --max-states 1000: no cut reported: $(tail -2 "$out/stdout")"
expect 64 "--max-states: '0' is not an integer" "${simulating[@]}" --explore --max-states 0

# --- -I takes one folder per use, in every position and spelling
expect 0 "" "$bin/bipc" check -I "$source/models" --include "$source" "$rendezvous" --root 'Top()'
expect 0 "" "$bin/bipc" check "$rendezvous" -I"$source/models" --include="$source" --root 'Top()'
expect 0 "" "$bin/smcbip" monitor --trace "$source/tests/smc/golden/traces/channel.jsonl" \
  "$out/holds.mtl" --model "$channel" -I "$source/models" --root 'System()'
expect 0 "" "$bin/smcbip" check -I "$source/models" --param t=0:100:50 "$channel" \
  "$out/sweep.mtl" --root 'System()' --delta 0.1 --threads 2

# --- the model, property and trace files: folders and devices refused, nothing read forever
expect 2 "the model file is a folder" "$bin/bipc" check "$out"
expect 2 "the model file is a device" "$bin/bipc" check /dev/zero
expect 65 "the model file is a device" "$bin/smcbip" simulate /dev/zero
expect 2 "the model file is a folder" "$bin/smcbip" check "$out" "$out/one.mtl"
expect 2 "the property file is a device" "$bin/smcbip" check "$channel" /dev/zero --root 'System()'
expect 2 "the trace is a device" "$bin/smcbip" monitor "$out/one.mtl" --trace /dev/zero
printf '// every query commented out\nconst k = 1\n' >"$out/none.mtl"
expect 2 "the property file holds no query to answer" "${check[@]/$out\/one.mtl/$out/none.mtl}"
head -c $(((4 << 20) + 1)) /dev/zero | tr '\0' ' ' >"$out/huge.mtl"
expect 2 "the property file is larger than 4 MiB" "${check[@]/$out\/one.mtl/$out/huge.mtl}"

# --- a plugin that cannot be loaded is the user's input error, through the firewall
expect 65 "smcbip: error: --compiled: no such file or folder: $out/none" \
  "$bin/smcbip" simulate --compiled "$out/none"
expect 2 "smcbip: error: --compiled: no such file or folder: $out/none" "${check[@]}" \
  --compiled "$out/none"

# --- output files: through links to their target, never over a FIFO, a device or a folder
explore=("$bin/smcbip" explore "$channel" "$out/sweep.mtl" --root 'System()' --delta 0.1 --threads 2)
echo old >"$out/target.csv"
ln -s target.csv "$out/link.csv"
expect 0 "" "${explore[@]}" --csv "$out/link.csv"
[[ -L $out/link.csv ]] || fail "--csv replaced the symbolic link by a file"
grep -q '^query,' "$out/target.csv" || fail "--csv did not write through the link to its target"
ln -s missing/none.csv "$out/dangling.csv"
expect 2 "no folder" "${explore[@]}" --csv "$out/dangling.csv"
mkfifo "$out/fifo.csv"
expect 2 "a FIFO, not a regular file" "${explore[@]}" --csv "$out/fifo.csv"
[[ -p $out/fifo.csv ]] || fail "--csv replaced a FIFO"
ln -s /dev/null "$out/null.svg"
expect 2 "it links to '/dev/null', a device, not a regular file" "${explore[@]}" \
  --plot "$out/null.svg"
[[ -c /dev/null ]] || fail "--plot replaced /dev/null"
expect 2 "a device, not a regular file" "${explore[@]}" --csv /dev/full
[[ -c /dev/full ]] || fail "--csv replaced /dev/full"
mkdir "$out/folder.csv"
expect 2 "a folder, not a regular file" "${explore[@]}" --csv "$out/folder.csv"
expect 2 "a FIFO, not a regular file" "$bin/bipc" ir "$rendezvous" --root 'Top()' -o "$out/fifo.csv"
expect 2 "it links to '/dev/null', a device" "$bin/bipc" dot "$rendezvous" --root 'Top()' \
  -o "$out/null.svg"
[[ -c /dev/null ]] || fail "bipc dot replaced /dev/null"
ls "$out" | grep -q '\.tmp' && fail "a temporary file was left behind: $(ls "$out")"

# --- --save-traces: a folder holding earlier traces is refused
expect 0 "" "${check[@]}" --save-traces "$out/traces"
expect 2 "already holds traces" "${check[@]}" --save-traces "$out/traces"

# --- --json says how to reproduce its results
"${check[@]}" --seed 7 --alpha 0.02 --json >"$out/check.json" || fail "check --json"
python3 - "$out/check.json" <<'PY' || fail "check --json lacks its settings"
import json, sys
s = json.load(open(sys.argv[1]))["settings"]
assert s["seed"] == 7 and s["alpha"] == 0.02 and s["beta"] == 0.05, s
assert s["delta"] == 0.1 and s["confidence"] == 0.95 and s["method"] == "auto", s
PY

# --- --version on every tool, --help without CLI11's enumeration mappings
for tool in "$bin/bipc" "$bin/smcbip"; do
  expect 0 "" "$tool" --version
  grep -q '0\.' "$out/stdout" || fail "$tool --version printed no version"
done
expect 0 "" "$bin/smcbip" check --version
for command in simulate check explore monitor; do
  expect 0 "" "$bin/smcbip" "$command" --help
  grep -qE -- '->|\{[a-z]+->|ENUM' "$out/stdout" && fail "smcbip $command --help: garbled choices"
done

if [[ $failures -gt 0 ]]; then
  echo "cli_robustness: $failures failures in $cases commands" >&2
  exit 1
fi
echo "cli_robustness: ok ($cases commands)"
