#!/usr/bin/env bash
# The projects bipc gen writes, built as a user builds them: against smcbip installed from this
# build (find_package), warnings as errors. Checks that
#  - the generated executable prints smcbip simulate's trace for the same options (three engines,
#    text and JSON lines), and smcbip --compiled runs the plugin the same way;
#  - --compiled with a model file refuses a plugin of another model (exit 65);
#  - a --no-main project has no executable, and binds the model's extern C++ (tests/codegen/lamp),
#    which the interpreter alone cannot run; a host program embeds it and steps its Component;
#  - the identity embedded in the sources is `bipc hash`'s, and it changes with an extern source.
#
# Usage: project_test.sh BUILD_DIR SOURCE_DIR WORK_DIR [EXTRA_CXX_FLAGS]
set -euo pipefail

if [[ $# -lt 3 ]]; then
  echo "usage: project_test.sh BUILD_DIR SOURCE_DIR WORK_DIR [EXTRA_CXX_FLAGS]" >&2
  exit 1
fi
build=$1
src=$2
work=$3
extra_flags=${4:-}
bin=$build/bin
compiler=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")
# Warnings are checked in the plain build; sanitizer instrumentation makes some of the
# compiler's flow warnings fire spuriously, so a sanitized run only builds and runs.
werror=-Werror
[[ -n $extra_flags ]] && werror=

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log" ||
  fail "cmake --install failed (see $work/install.log)"

# generate NAME FILE ROOT [bipc gen options...]: the project in $work/NAME, built in $work/NAME/build.
generate() {
  local name=$1 file=$2 root=$3
  shift 3
  "$bin/bipc" gen "$file" --root "$root" -o "$work/$name" "$@" || fail "bipc gen $file"
  cmake -S "$work/$name" -B "$work/$name/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
    -DCMAKE_CXX_COMPILER="$compiler" -DCMAKE_CXX_FLAGS="$werror $extra_flags" \
    > "$work/$name.configure.log" 2>&1 || { cat "$work/$name.configure.log"; fail "configure $name"; }
  cmake --build "$work/$name/build" -j2 > "$work/$name.build.log" 2>&1 ||
    { cat "$work/$name.build.log"; fail "build $name"; }
  if [[ -n $werror ]] && grep -q "warning:" "$work/$name.build.log"; then
    cat "$work/$name.build.log"
    fail "warnings building $name"
  fi
}

# same LABEL EXPECTED_CMD -- ACTUAL_CMD: both give the same stdout and exit code.
same() {
  local label=$1
  shift
  local -a expected=() actual=()
  while [[ $1 != -- ]]; do expected+=("$1"); shift; done
  shift
  actual=("$@")
  local e_code=0 a_code=0
  "${expected[@]}" > "$work/expected.out" 2> /dev/null || e_code=$?
  "${actual[@]}" > "$work/actual.out" 2> "$work/actual.err" || a_code=$?
  if ! cmp -s "$work/expected.out" "$work/actual.out" || [[ $e_code != "$a_code" ]]; then
    cat "$work/actual.err" >&2
    diff "$work/expected.out" "$work/actual.out" | head -20 >&2 || true
    fail "$label: output or exit code differs ($e_code vs $a_code)"
  fi
  [[ -s $work/expected.out ]] || fail "$label: no output"
}

channel=$src/models/channel.bip
generate channel "$channel" 'System()' --namespace flight::channel
exe=$work/channel/build/flight_channel_simulate
[[ -x $exe ]] || fail "no executable flight_channel_simulate"
for engine in reference optimised multithread; do
  same "channel $engine" "$bin/smcbip" simulate "$channel" --root 'System()' --engine "$engine" \
    --seed 5 --limit 300 -- "$exe" --engine "$engine" --seed 5 --limit 300
done
same "channel jsonl" "$bin/smcbip" simulate "$channel" --root 'System()' --seed 9 --limit 200 \
  --trace jsonl -- "$exe" --seed 9 --limit 200 --trace jsonl
same "channel --compiled" "$bin/smcbip" simulate "$channel" --root 'System()' --seed 5 --limit 300 \
  -- "$bin/smcbip" simulate --compiled "$work/channel" --seed 5 --limit 300
same "channel FILE --compiled" "$bin/smcbip" simulate "$channel" --root 'System()' --seed 6 \
  --limit 300 -- "$bin/smcbip" simulate "$channel" --root 'System()' --compiled "$work/channel" \
  --seed 6 --limit 300

# Statistical checking on the compiled model takes the same runs as on the interpreter.
check_json() {
  "$bin/smcbip" check "$channel" "$src/models/channel.mtl" --root 'System()' --delta 0.05 \
    --seed 3 --threads 2 --json "$@" | grep -v '"seconds"'
}
check_json > "$work/check_interpreted.json" || [[ $? == 1 ]]
check_json --compiled "$work/channel" > "$work/check_compiled.json" || [[ $? == 1 ]]
cmp -s "$work/check_interpreted.json" "$work/check_compiled.json" ||
  fail "smcbip check --compiled answers differ: $(diff "$work/check_interpreted.json" \
    "$work/check_compiled.json" | head -10)"
grep -q '"samples"' "$work/check_compiled.json" || fail "smcbip check --compiled: no results"

code=0
"$bin/smcbip" simulate "$src/models/two_exponentials.bip" --root 'System()' \
  --compiled "$work/channel" --limit 3 > /dev/null 2> "$work/other.err" || code=$?
[[ $code == 65 ]] || fail "--compiled with another model's file: exit $code, expected 65"
grep -q "holds another model" "$work/other.err" || fail "no message for another model's plugin"

code=0
"$bin/smcbip" simulate --compiled "$work/nowhere" > /dev/null 2> "$work/missing.err" || code=$?
[[ $code == 65 ]] || fail "--compiled with a missing folder: exit $code, expected 65"

lamp=$src/tests/codegen/lamp/lamp.bip
generate lamp "$lamp" 'Top()' --no-main
[[ ! -e $work/lamp/main.cpp ]] || fail "--no-main wrote main.cpp"
compgen -G "$work/lamp/build/*_simulate" > /dev/null && fail "--no-main built an executable"
"$bin/smcbip" simulate --compiled "$work/lamp" --seed 1 --limit 4 > "$work/lamp.out" ||
  fail "the lamp's plugin did not run"
for level in 4 13 40 121; do
  grep -qx "level $level" "$work/lamp.out" || fail "the lamp's extern C++ did not give level $level"
done
same "lamp FILE --compiled" "$bin/smcbip" simulate --compiled "$work/lamp" --seed 2 --limit 5 -- \
  "$bin/smcbip" simulate "$lamp" --root 'Top()' --compiled "$work/lamp" --seed 2 --limit 5
code=0
"$bin/smcbip" simulate "$lamp" --root 'Top()' --seed 1 --limit 4 > /dev/null 2>&1 || code=$?
[[ $code != 0 ]] || fail "the interpreter ran the lamp without its extern C++"
# The lamp's extern names it in Latin-1: its JSONL trace writes U+FFFD for that byte and stays
# JSON (without the replacement, the trace ends in an internal error).
"$bin/smcbip" simulate --compiled "$work/lamp" --seed 1 --limit 2 --trace jsonl \
  > "$work/lamp.jsonl" 2> "$work/lamp_jsonl.err" || fail "the lamp's JSONL trace failed"
python3 - "$work/lamp.jsonl" <<'PY' || fail "the lamp's JSONL trace does not name it d\ufffdbut"
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1], encoding="utf-8") if l.startswith("{")]
names = [l["data"]["ROOT.lamp.name"] for l in lines if "data" in l]
assert names == ["", "d\ufffdbut", "d\ufffdbut"], names
PY

# A host program embedding the --no-main library: it steps the Component and reads its data.
mkdir -p "$work/host"
cat > "$work/host/CMakeLists.txt" <<EOF
cmake_minimum_required(VERSION 3.25)
project(host LANGUAGES CXX)
set(CMAKE_CXX_STANDARD 20)
add_subdirectory("$work/lamp" lamp)
add_executable(host host.cpp)
target_compile_options(host PRIVATE -Wall -Wextra)
target_link_libraries(host PRIVATE bip_model)
EOF
cat > "$work/host/host.cpp" <<'EOF'
#include <iostream>

#include "model.h"

int main() {
  bip_model::Component lamp;
  const auto level = lamp.find_data("ROOT.lamp", "level");
  if (!level || !lamp.start()) return 1;
  for (int i = 0; i < 4; ++i) {
    if (!lamp.step().stepped) return 1;
  }
  std::cout << bip_model::Component::model_hash() << " " << lamp.read(level->atom, level->slot).i
            << "\n";
  return 0;
}
EOF
cmake -S "$work/host" -B "$work/host/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_CXX_COMPILER="$compiler" -DCMAKE_CXX_FLAGS="$werror $extra_flags" \
  > "$work/host.log" 2>&1 && cmake --build "$work/host/build" -j2 >> "$work/host.log" 2>&1 ||
  { cat "$work/host.log"; fail "the host program did not build"; }
host_out=$("$work/host/build/host" 2> /dev/null) || fail "the host program failed"

hash=$("$bin/bipc" hash "$lamp" --root 'Top()')
[[ $(tail -n 1 <<<"$host_out") == "$hash 121" ]] ||
  fail "the host program ended with '$(tail -n 1 <<<"$host_out")', not '$hash 121'"
grep -qx "level 40" <<<"$host_out" || fail "the host program's model printed no 'level 40'"
grep -q "kModelHash = \"$hash\"" "$work/lamp/model.h" || fail "model.h does not carry bipc hash's $hash"
mkdir -p "$work/lamp_copy"
cp "$src/tests/codegen/lamp/"* "$work/lamp_copy/"
{ echo "// a comment moves every line"; cat "$lamp"; } > "$work/lamp_copy/lamp.bip"
[[ $("$bin/bipc" hash "$work/lamp_copy/lamp.bip" --root 'Top()') == "$hash" ]] ||
  fail "the hash changed with the model's folder or a comment"
sed -i 's/3 \* level + 1/3 * level + 2/' "$work/lamp_copy/lamp.cpp"
[[ $("$bin/bipc" hash "$work/lamp_copy/lamp.bip" --root 'Top()') != "$hash" ]] ||
  fail "the hash did not change with the extern source"
# The installed prefix is some hundreds of megabytes; the logs and generated files stay.
rm -rf "$work/prefix"
echo "generated projects: all checks passed"
