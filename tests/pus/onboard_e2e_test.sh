#!/usr/bin/env bash
# pus_onboard and pus-console end to end over UDP on the loopback: the program announces the
# model bipc hash names, the console runs onboard_e2e.tc, and its log must show the rows of
# onboard_e2e.expected (the periodic reports apart): the ping's verification, housekeeping
# reports every 200 ms while enabled, an ST12 limit violation raising an ST05 event whose ST19
# action ST08 performs, a TC released by ST11 at its time, a malformed TC refused with
# TM[1,2], and ST23 creating a file in the repository root the test adds to the mission.
#
# PACKETS, if given, receives the console's --packet-log (every TM received, as hex) once the
# run is checked, for pus.onboard_sim to compare with the model simulated.
#
# Usage: onboard_e2e_test.sh PUS_ONBOARD PUS_CONSOLE BIPC MODEL MISSION SCRIPT EXPECTED [PACKETS]
set -euo pipefail
onboard=$1
console=$2
bipc=$3
model=$4
mission=$5
script=$6
expected=$7
packets=${8:-}
[[ -z $packets ]] || rm -f "$packets"

work=$(mktemp -d)
pid=""
cleanup() {
  [[ -n $pid ]] && kill "$pid" 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
# The bundled mission with a repository root of the test's own.
mkdir -p "$work/files/logs"
sed '1s|{|{"file_repository": "'"$work/files"'",|' "$mission" >"$work/mission.json"

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# A mission refused: its error located in the file, exit 2, nothing started.
printf '{"apid": 18,\n "parameters": [], "colour": 1}\n' >"$work/bad.json"
status=0
"$onboard" --mission "$work/bad.json" 2>"$work/bad.err" >/dev/null || status=$?
[[ $status == 2 ]] || fail "a refused mission exits with $status"
grep -qx "$work/bad.json:2:20: error: unknown key \"colour\"" "$work/bad.err" ||
  fail "the refused mission's error: $(cat "$work/bad.err")"

"$onboard" --mission "$work/mission.json" --port 0 --duration-ms 5500 >"$work/onboard.out" 2>&1 &
pid=$!
for _ in $(seq 100); do
  grep -q 'listening on udp' "$work/onboard.out" && break
  sleep 0.05
done
port=$(grep -o 'udp 127.0.0.1:[0-9]*' "$work/onboard.out" | cut -d: -f2) ||
  fail "pus_onboard does not listen: $(cat "$work/onboard.out")"

hash=$("$bipc" hash "$model" --root 'Onboard()')
head -1 "$work/onboard.out" | grep -qx "pus_onboard: running model $hash" ||
  fail "pus_onboard does not announce bipc hash's $hash"

"$console" script "$script" --port "$port" --wait 300 --log "$work/log" \
  --packet-log "$work/packets" >/dev/null ||
  fail "pus-console exited with $?"
wait "$pid" || fail "pus_onboard exited with $?"
pid=""
tail -1 "$work/onboard.out" | grep -q ': 9 TCs received (0 dropped)' ||
  fail "pus_onboard's summary: $(tail -1 "$work/onboard.out")"

# The rows but the periodic ones, without the index, time and TM sequence count columns.
tail -n +2 "$work/log" | grep -v -E '^[0-9]+ +TM  (3    25|9    2) ' | cut -c7-20,35-48,56- \
  >"$work/rows"
grep -v '^#' "$expected" >"$work/expected"
diff "$work/expected" "$work/rows" >&2 || fail "the console's log differs from $expected"

# Housekeeping structure 1 was on for about 1 s (from its [1,7] to that of [3,6]): 5 reports,
# give or take one (as the TCs' real arrival falls), 200 ms apart to the millisecond (the
# console truncates the fine time).
hk=$(grep -E '^[0-9]+ +TM  3    25 .*structure 1, values 1105199104, 20, 1$' "$work/log" |
  cut -c21-34 | tr -d ' ')
count=$(echo "$hk" | wc -l)
[[ $count -ge 4 && $count -le 6 ]] || fail "$count housekeeping reports: $hk"
echo "$hk" | awk 'NR > 1 { gap = int(($1 - last) * 1000 + 0.5); if (gap < 199 || gap > 201) bad = 1 }
                  { last = $1 } END { exit bad }' || fail "housekeeping reports not 200 ms apart: $hk"
# Time reports, once a second from start.
grep -qE '^[0-9]+ +TM  9    2    2\.000 ' "$work/log" || fail "no time report at 2 s"
# The scheduled ping ran at 4 s on board.
grep -qE '^[0-9]+ +TM  17   2    4\.0[0-4][0-9] ' "$work/log" || fail "the [11,4] ping not at 4 s"
# [23,1] made the file, its maximum size of octets.
[[ $(stat -c %s "$work/files/logs/e2e.bin") == 64 ]] || fail "[23,1] did not create logs/e2e.bin"
[[ -z $packets ]] || cp "$work/packets" "$packets"
echo "pus_onboard: end-to-end run checked"
