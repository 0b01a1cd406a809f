#!/usr/bin/env bash
# pus-console as a whole tool: what it prints, the files it writes and its exit codes.
#
# Usage: console_cli_test.sh PUS_CONSOLE
set -u

readonly console=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0

# expect NAME CODE STDOUT_PART STDERR_PART -- COMMAND...: the exit code is CODE and the outputs
# contain the parts (an empty part checks nothing).
expect() {
  local name=$1 code=$2 out_part=$3 err_part=$4
  shift 5
  "$@" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  if [[ $got -ne $code ]] || { [[ -n $out_part ]] && ! grep -qF -- "$out_part" "$tmp/out"; } ||
    { [[ -n $err_part ]] && ! grep -qF -- "$err_part" "$tmp/err"; }; then
    echo "FAIL $name: exit $got (expected $code)"
    sed 's/^/  stdout: /' "$tmp/out"
    sed 's/^/  stderr: /' "$tmp/err"
    failures=$((failures + 1))
  fi
}

# TC[17,1], APID 0, count 0: 18 00 c0 00 00 06, PUS version 2 with all ack flags 2f, 11 01,
# source 00 00, then CRC-16/CCITT-FALSE of those eleven octets, 0x7958.
expect "encode 17 1" 0 "1800c00000062f110100007958" "" -- "$console" encode 17 1
expect "encode --out" 0 "" "" -- "$console" encode 3 5 --sid 1 2 --apid 0x12 --out "$tmp/tc.bin"
expect "decode --in" 0 \
  "TC[3,5] enable periodic housekeeping reports: structures 1, 2" "" -- \
  "$console" decode --in "$tmp/tc.bin"
expect "decode hex" 0 "TC  17   1    -             0      0x0    0      valid     TC[17,1]" "" -- \
  "$console" decode "18 00 c0 00 00 06 2f 11 01 00 00 79 58"
expect "decode hex words" 0 "TC[17,1] are-you-alive connection test" "" -- \
  "$console" decode 1800c000 0006 2f11010000 7958
expect "decode bad crc" 2 "" "pus-console: error: malformed packet: bad-crc at byte " -- \
  "$console" decode 1800c00000062f110100007959
expect "decode bad hex" 2 "" "HEX: expected a hex digit or a separator at character 3" -- \
  "$console" decode "18zz"
expect "decode nothing" 2 "" "decode: expected HEX or --in FILE" -- "$console" decode
expect "encode bad field" 2 "" "--sid: TC[17,1] (are-you-alive connection test) takes no such" -- \
  "$console" encode 17 1 --sid 4
expect "no command" 2 "" "expected a command" -- "$console"
expect "interactive needs a port" 2 "" "--port is required" -- "$console" interactive

cat >"$tmp/good.tc" <<'SCRIPT'
# a connection test, then a parameter report
17 1 --apid 0x12
20 1 --param 7   # parameter 7
SCRIPT
expect "script without link" 0 \
  "2     TC  20   1    -             0      0x0    0      not sent  TC[20,1] report parameter" \
  "" -- "$console" script "$tmp/good.tc" --log "$tmp/good.log"
if ! cmp -s "$tmp/out" "$tmp/good.log"; then
  echo "FAIL script log: the log differs from the table printed"
  failures=$((failures + 1))
fi

printf '17 1\n\n3 5 --sid 1 x\n' >"$tmp/bad.tc"
expect "script error" 2 "" "$tmp/bad.tc:3:13: error: --sid: expected a structure ID" -- \
  "$console" script "$tmp/bad.tc" --log "$tmp/bad.log"
if [[ -e $tmp/bad.log ]]; then
  echo "FAIL script error: a log was written"
  failures=$((failures + 1))
fi
if [[ -s $tmp/out ]]; then
  echo "FAIL script error: rows were printed"
  failures=$((failures + 1))
fi

expect "interactive from a pipe" 2 "" "<stdin>:1:1: error: SERVICE: expected a TC" -- \
  bash -c "printf '99 1\n' | '$console' interactive --port 9 --wait 0"

[[ $failures -eq 0 ]] && echo "pus-console CLI: all checks pass"
exit $((failures > 0))
