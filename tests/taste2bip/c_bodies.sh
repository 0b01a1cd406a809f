#!/usr/bin/env bash
# Designs whose functions have C bodies, run as users run them: taste2bip, bipc gen, the project
# built against smcbip installed from this build (C and C++ warnings as errors for the bundled
# design), then smcbip simulate and check with --compiled. Checks that
#  - tests/taste2bip/c_bodies: the bodies' printed lines are c_bodies/expected_output.txt (a
#    body's synchronous call returns its callee's result, its context parameter is set), and
#    c_bodies/properties.mtl gets the answers its header derives by hand, on one thread;
#  - the same check on two threads ends in the model error that says why;
#  - the real Demo_ContextParams of ../shared (when present): a C body calls another one
#    synchronously with a SEQUENCE and prints the sums 0, 2, 4; SAMV71's interface tests build
#    and run.
#
# Usage: c_bodies.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -euo pipefail

[[ $# -eq 3 ]] || { echo "usage: c_bodies.sh BUILD_DIR SOURCE_DIR WORK_DIR" >&2; exit 1; }
build=$1
src=$2
work=$3
bin=$build/bin
compiler=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log" ||
  fail "cmake --install failed (see $work/install.log)"

# translate_and_build NAME VIEW [C flags]: the design's package in $work/NAME, its project in
# $work/NAME.gen.
translate_and_build() {
  local name=$1 view=$2 cflags=${3:-}
  "$bin/taste2bip" "$view" -o "$work/$name" > "$work/$name.report" || fail "taste2bip $view"
  "$bin/bipc" gen "$work/$name/taste.bip" --root 'Syst()' -o "$work/$name.gen" ||
    fail "bipc gen $name"
  cmake -S "$work/$name.gen" -B "$work/$name.gen/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
    -DCMAKE_CXX_COMPILER="$compiler" -DCMAKE_C_FLAGS="$cflags" \
    -DCMAKE_CXX_FLAGS="${cflags:+-Werror}" > "$work/$name.configure.log" 2>&1 ||
    { cat "$work/$name.configure.log"; fail "configure $name"; }
  cmake --build "$work/$name.gen/build" -j2 > "$work/$name.build.log" 2>&1 ||
    { cat "$work/$name.build.log"; fail "build $name"; }
  if [[ -n $cflags ]] && grep -q "warning:" "$work/$name.build.log"; then
    cat "$work/$name.build.log"
    fail "warnings building $name"
  fi
}

design=$src/tests/taste2bip/c_bodies
translate_and_build sensor "$design/interfaceview.xml" "-Wall -Wextra -Werror"
model=$work/sensor/taste.bip

"$bin/smcbip" simulate "$model" --root 'Syst()' --compiled "$work/sensor.gen" --seed 1 \
  --limit 60 > "$work/sensor.trace" 2>&1 || fail "simulate sensor"
grep -v '^\[BIP ENGINE\]' "$work/sensor.trace" > "$work/sensor.output" || true
diff -u "$design/expected_output.txt" "$work/sensor.output" || fail "sensor's printed lines differ"

"$bin/smcbip" check "$model" "$design/properties.mtl" --root 'Syst()' \
  --compiled "$work/sensor.gen" --seed 1 --threads 1 > "$work/sensor.check" 2>&1 ||
  { cat "$work/sensor.check"; fail "check sensor on one thread"; }
grep -v '^sensor:' "$work/sensor.check" | grep -E '^  sprt:' > "$work/sensor.verdicts"
expected=("holds" "holds" "holds" "holds")
[[ $(wc -l < "$work/sensor.verdicts") -eq ${#expected[@]} ]] ||
  { cat "$work/sensor.check"; fail "check sensor: not one verdict per query"; }
for i in "${!expected[@]}"; do
  line=$(sed -n "$((i + 1))p" "$work/sensor.verdicts")
  [[ $line == "  sprt: ${expected[$i]},"* ]] ||
    fail "query $((i + 1)): expected '${expected[$i]}', got '$line'"
done

# Two threads at once would share the bodies' data: the runs of the second end in an error.
status=0
"$bin/smcbip" check "$model" "$design/properties.mtl" --root 'Syst()' \
  --compiled "$work/sensor.gen" --seed 1 --threads 2 > "$work/sensor.threads" 2>&1 || status=$?
[[ $status -ne 0 ]] || fail "check on two threads succeeded"
grep -q 'run with --threads 1' "$work/sensor.threads" ||
  { cat "$work/sensor.threads"; fail "check on two threads does not say why it failed"; }

demo=$src/../shared/data/taste/esa-kazoo/Demo_ContextParams
if [[ -f $demo/InterfaceView.aadl ]]; then
  translate_and_build context_params "$demo/InterfaceView.aadl"
  "$bin/smcbip" simulate "$work/context_params/taste.bip" --root 'Syst()' \
    --compiled "$work/context_params.gen" --seed 1 --limit 120 > "$work/context_params.trace" 2>&1 ||
    fail "simulate Demo_ContextParams"
  sums=$(grep -o 'result of computation: [0-9]*' "$work/context_params.trace" | head -3 |
    awk '{print $4}' | tr '\n' ' ')
  [[ $sums == "0 2 4 " ]] || fail "Demo_ContextParams: sums '$sums', expected '0 2 4 '"
  grep -q 'startup done: 42 -42' "$work/context_params.trace" ||
    fail "Demo_ContextParams: context parameters not set"
  # Bodies written against asn1scc's types (SEQUENCE, ENUMERATED named after their type) and
  # calling through protected, unprotected and sporadic interfaces compile and run.
  rtems=$src/../shared/data/taste/n7space-TASTE-SAMV71-RTEMS-Tests/samv71-rtems-interfaces
  translate_and_build rtems_interfaces "$rtems/interfaceview.xml"
  "$bin/smcbip" simulate "$work/rtems_interfaces/taste.bip" --root 'Syst()' \
    --compiled "$work/rtems_interfaces.gen" --seed 1 --limit 300 > "$work/rtems.trace" 2>&1 ||
    fail "simulate samv71-rtems-interfaces"
else
  echo "skipped Demo_ContextParams: ../shared/data/taste is not beside the source tree"
fi
# The installed prefix is some hundreds of megabytes; the logs and generated files stay.
rm -rf "$work/prefix"
echo "c_bodies: all checks passed"
