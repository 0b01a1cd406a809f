#!/usr/bin/env bash
# pus_onboard.bip runs compiled (its atoms call the services' C++ through the plugin): a
# simulation ends at its step limit, and smcbip check answers properties.mtl. The horizon is cut
# to 3 s to keep the test quick; on it the four requirement queries hold (on the full 10 s as
# well: see properties.mtl), and the last one, which needs a long enough run for the ground to
# put the temperature out of its limits, is only answered.
#
# Usage: onboard_model_test.sh SMCBIP PLUGIN MODEL PROPERTIES
set -euo pipefail
smcbip=$1
plugin=$2
model=$3
properties=$4

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

"$smcbip" simulate "$model" --compiled "$plugin" --seed 3 --limit 2000 --silent >/dev/null ||
  fail "smcbip simulate --compiled exited with $?"

# Exit 1: a query does not hold (the last one, on this horizon).
status=0
out=$("$smcbip" check "$model" "$properties" --compiled "$plugin" --seed 1 \
  --param 'horizon={3000}' 2>/dev/null) || status=$?
[[ $status == 0 || $status == 1 ]] || fail "smcbip check exited with $status"
verdicts=$(echo "$out" | grep -E '^  sprt: ' | cut -d, -f1)
expected=$'  sprt: holds\n  sprt: holds\n  sprt: holds\n  sprt: holds'
[[ $(echo "$verdicts" | head -4) == "$expected" ]] || fail "not every requirement holds: $out"
[[ $(echo "$verdicts" | wc -l) == 5 ]] || fail "not five answers: $out"
echo "pus_onboard: model checked"
