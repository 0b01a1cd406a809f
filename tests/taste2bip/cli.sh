#!/usr/bin/env bash
# The taste2bip command line: exit codes, located errors, nothing written on failure.
# Usage: cli.sh BIN_DIR SOURCE_DIR
set -u
bin=$1/taste2bip
golden=$2/tests/taste2bip/golden
work=$(mktemp -d "${TMPDIR:-/tmp}/taste2bip_cli.XXXXXX") || exit 1
trap 'rm -rf -- "$work"' EXIT
failures=0

# expect CODE TEXT -- ARGS...: the exit code, and TEXT in stderr (empty: anything).
expect() {
  local code=$1 text=$2
  shift 3
  "$bin" "$@" > "$work/stdout" 2> "$work/stderr" < /dev/null
  local actual=$?
  if [[ $actual -ne $code ]] || { [[ -n $text ]] && ! grep -qF -- "$text" "$work/stderr"; }; then
    echo "FAIL: taste2bip $* gave $actual (expected $code, stderr with '$text'):"
    sed 's/^/+ /' "$work/stderr"
    failures=$((failures + 1))
  fi
}

view=$golden/sporadic_queue/interfaceview.xml
expect 0 "" -- --version
expect 0 "" -- --help
expect 2 "" -- "$view"
expect 2 "'not-a-mode' is not one of interval, uniform, zero" -- "$view" -o "$work/a" --wcet not-a-mode
expect 2 "FUNCTION=FILE" -- "$view" -o "$work/a" --atom Feeder
expect 2 "is not a BIP identifier" -- "$view" -o "$work/a" --package 'my-package'
expect 2 "no-such-view.xml" -- "$work/no-such-view.xml" -o "$work/a"
expect 2 "no-such.asn" -- "$view" --dataview "$work/no-such.asn" -o "$work/a"
expect 2 "is not a folder" -- "$view" --sdl "$work/no-such-folder" -o "$work/a"
expect 2 "the C/C++ source folder" -- "$view" --src "$work/no-such-folder" -o "$work/a"
[[ -e $work/a ]] && { echo "FAIL: a refused run wrote $work/a"; failures=$((failures + 1)); }

# A type the data view lacks: located at the parameter, nothing written.
mkdir -p "$work/bad"
sed 's/T-Count/T-Missing/' "$view" > "$work/bad/interfaceview.xml"
cp "$golden/sporadic_queue/dataview.asn" "$work/bad/"
expect 2 "interfaceview.xml:7:5: error: type 'T-Missing' is not in the data view" -- \
  "$work/bad/interfaceview.xml" -o "$work/b"
[[ -e $work/b ]] && { echo "FAIL: a refused design wrote $work/b"; failures=$((failures + 1)); }

# The output folder cannot be a file.
touch "$work/file"
expect 2 "" -- "$view" --atom "Feeder=$golden/sporadic_queue/feeder.bip" -o "$work/file"

# Success writes the four files and says so.
expect 0 "" -- "$view" --atom "Feeder=$golden/sporadic_queue/feeder.bip" -o "$work/ok" --package q
for f in q.bip q_faulty.bip q_requirements.bip q_report.txt; do
  [[ -f $work/ok/$f ]] || { echo "FAIL: no $f written"; failures=$((failures + 1)); }
done
grep -q "^package q$" "$work/ok/q.bip" || { echo "FAIL: q.bip is not package q"; failures=$((failures + 1)); }

[[ $failures -eq 0 ]] && echo "PASS taste2bip command line"
exit $((failures > 0))
