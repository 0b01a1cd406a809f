#!/usr/bin/env bash
# The scenario of onboard_e2e.tc run as a simulation of pus_onboard.bip (pus_onboard_sim: the
# same component on a virtual clock, the console's session code as its ground) must give the
# packets the deployed pus_onboard gave pus-console on the loopback in pus.onboard_e2e (its
# --packet-log, the fixture this test requires): the same table rows as onboard_e2e.expected,
# and the same TM octets, compared by pus_tm_compare apart from the times, sequence counts and
# CRCs, the periodic reports apart: housekeeping [3,25] 4..6 times (structure 1 on for about
# 1 s at 200 ms: 5, give or take one as the real arrival of [3,5] and [3,6] falls; the
# simulation's [1,7] of [3,6] comes 2 ms before the fifth is due, so 4), time reports [9,2]
# 4..5 times (once a second from the program's start; the console hears those of its 4.6 s
# from its first TC, which it sends a few ms after the program starts, up to 1 s late).
#
# Usage: onboard_sim_test.sh PUS_ONBOARD_SIM PUS_TM_COMPARE MISSION SCRIPT EXPECTED DEPLOYED
set -euo pipefail
sim=$1
compare=$2
mission=$3
script=$4
expected=$5
deployed=$6

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The bundled mission with a repository root of the test's own, as pus.onboard_e2e runs it.
mkdir -p "$work/files/logs"
sed '1s|{|{"file_repository": "'"$work/files"'",|' "$mission" >"$work/mission.json"

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# A refused script line: located, exit 2, no log written.
printf '17 1\n23 1 --file a\n' >"$work/bad.tc"
status=0
"$sim" --mission "$work/mission.json" --script "$work/bad.tc" --log "$work/bad.log" \
  2>"$work/bad.err" >/dev/null || status=$?
[[ $status == 2 && ! -e $work/bad.log ]] || fail "a refused script: exit $status"
grep -q "^$work/bad.tc:2:14: error: .*got no --size$" "$work/bad.err" ||
  fail "the refused script's error: $(cat "$work/bad.err")"

"$sim" --mission "$work/mission.json" --script "$script" --wait 300 --log "$work/log" \
  --packet-log "$work/packets" >"$work/out" || fail "pus_onboard_sim exited with $?"
tail -1 "$work/out" | grep -q ': 9 TCs received (0 dropped)' ||
  fail "pus_onboard_sim's summary: $(tail -1 "$work/out")"

# The rows as onboard_e2e_test.sh compares them.
tail -n +2 "$work/log" | grep -v -E '^[0-9]+ +TM  (3    25|9    2) ' | cut -c7-20,35-48,56- \
  >"$work/rows"
grep -v '^#' "$expected" | diff - "$work/rows" >&2 || fail "the simulation's log differs from $expected"
# On a virtual clock the times are exact: the scheduled ping at 4 s plus the model's delays.
grep -qE '^[0-9]+ +TM  17   2    4\.00[0-9] ' "$work/log" || fail "the [11,4] ping not at 4 s"

[[ $(stat -c %s "$work/files/logs/e2e.bin") == 64 ]] || fail "[23,1] did not create logs/e2e.bin"

[[ -s $deployed ]] || fail "no packets of the deployed run: $deployed"
"$compare" "$deployed" "$work/packets" --count 3,25=4..6 --count 9,2=4..5 ||
  fail "the simulation's TM packets differ from the deployed program's"
