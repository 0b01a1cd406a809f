#!/usr/bin/env bash
# hello_flight's mission: 40 cycles of 10 ms; the heart beats every 50 ms, then every 20 ms after
# the halfway write at 200 ms, when telecommand 7 is fed. On a virtual clock the beats fire at
# 50, 100, 150, 200 ms, then 220, 240, ..., 400 ms: 4 + 10 = 14 beats, the telecommand taken
# at 200 ms. In real time the loop runs on the platform clock and must report the same.
#
# Usage: hello_flight_test.sh HELLO_FLIGHT BIPC MODEL
set -euo pipefail
hello=$1
bipc=$2
model=$3

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

hash=$("$bipc" hash "$model" --root 'Flight()')
for mode in --virtual-clock ""; do
  out=$("$hello" $mode) || fail "hello_flight $mode exited with $?"
  echo "$out" | head -1 | grep -qx "hello_flight: running model $hash" ||
    fail "hello_flight $mode does not announce bipc hash's $hash"
  echo "$out" | grep -qx "telecommand taken at 200 ms" || fail "$mode: no telecommand at 200 ms"
  [[ $(echo "$out" | grep -c '^beat at') == 14 ]] || fail "$mode: not 14 beats: $out"
  echo "$out" | grep -qx "beat at 220 ms" || fail "$mode: the period was not shortened"
  echo "$out" | tail -1 | grep -qx "mission complete at 400 ms: 14 beats, last telecommand 7" ||
    fail "$mode: wrong summary: $(echo "$out" | tail -1)"
done
echo "hello_flight: mission checked"
