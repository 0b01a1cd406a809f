#!/usr/bin/env bash
# Installs the build tree into a scratch prefix, builds tests/package/consumer against it with
# find_package(smcbip), and checks that the consumer (directly and through its shared module)
# and the installed tools print what the build tree's smcbip and bipc print for the same model.
#
# Usage: install_consumer.sh SOURCE_DIR BUILD_DIR CONFIG SCRATCH SMCBIP BIPC MODEL ROOT CMAKE
#                            [consumer configure arguments...]
set -euo pipefail

if [[ $# -lt 9 ]]; then
  echo "usage: $0 SOURCE_DIR BUILD_DIR CONFIG SCRATCH SMCBIP BIPC MODEL ROOT CMAKE [ARGS...]" >&2
  exit 2
fi
source_dir=$1 build_dir=$2 config=$3 scratch=$4 smcbip=$5 bipc=$6 model=$7 root=$8 cmake=$9
shift 9
consumer_src=$source_dir/tests/package/consumer
prefix=$scratch/prefix
consumer_build=$scratch/consumer
seed=7
limit=40

fail() {
  echo "package test: FAILED: $*" >&2
  exit 1
}

# Runs a command, keeping its output in a log that is shown when it fails.
logged() {
  local log=$1
  shift
  if ! "$@" >"$log" 2>&1; then
    cat "$log" >&2
    fail "command failed (log above, also in $log): $*"
  fi
}

rm -rf "$scratch"
mkdir -p "$scratch"

logged "$scratch/install.log" "$cmake" --install "$build_dir" --config "$config" --prefix "$prefix"
for installed in bin/bipc bin/smcbip lib/cmake/smcbip/smcbipConfig.cmake \
                 lib/cmake/smcbip/smcbipConfigVersion.cmake include/bipc/bipc.h \
                 include/bipc/ir/ir.h include/engines/engines.h \
                 include/engines/api/code_ops.h include/engines/api/compiled_model.h \
                 include/engines/api/plugin_abi.h; do
  [[ -e $prefix/$installed ]] || fail "cmake --install did not install $installed"
done
# The engines install their public API alone: engines.h and api/ (generated code and host
# programs compile against nothing else of them).
internal=$(find "$prefix/include/engines" -name '*.h' ! -path "$prefix/include/engines/api/*" \
           ! -path "$prefix/include/engines/engines.h")
[[ -z $internal ]] || fail "cmake --install installed headers of the engines' inside: $internal"
if grep -rqF "$source_dir" "$prefix/lib/cmake/smcbip"; then
  fail "the installed package names the source tree:" \
       "$(grep -rlF "$source_dir" "$prefix/lib/cmake/smcbip")"
fi

logged "$scratch/configure.log" "$cmake" -S "$consumer_src" -B "$consumer_build" \
  -DCMAKE_PREFIX_PATH="$prefix" -DCONSUMER_MODEL="$model" -DCONSUMER_ROOT="$root" "$@"
found_dir=$(sed -n 's/^smcbip_DIR:PATH=//p' "$consumer_build/CMakeCache.txt")
[[ $found_dir == "$prefix/"* ]] || fail "the consumer found smcbip in '$found_dir', not in $prefix"
logged "$scratch/build.log" "$cmake" --build "$consumer_build" --parallel 2

# Runs one simulation into the file named first; the exit code goes to the file's .code.
simulate() {
  local out=$1
  shift
  local code=0
  "$@" "$model" --root "$root" --seed "$seed" --limit "$limit" >"$out" 2>"$out.err" || code=$?
  echo "$code" >"$out.code"
}

simulate "$scratch/expected.txt" "$smcbip" simulate
[[ -s $scratch/expected.txt ]] ||
  fail "smcbip simulate printed nothing: $(cat "$scratch/expected.txt.err")"
simulate "$scratch/installed.txt" "$prefix/bin/smcbip" simulate
simulate "$scratch/consumer.txt" "$consumer_build/consumer"
simulate "$scratch/plugin.txt" "$consumer_build/consumer" --plugin \
  "$consumer_build/libconsumer_plugin.so"

status=0
for run in installed consumer plugin; do
  if ! diff -u "$scratch/expected.txt" "$scratch/$run.txt" >"$scratch/$run.diff"; then
    echo "package test: the $run run differs from smcbip simulate" \
         "(its stderr: $(cat "$scratch/$run.txt.err")):" >&2
    head -40 "$scratch/$run.diff" >&2
    status=1
  elif ! cmp -s "$scratch/expected.txt.code" "$scratch/$run.txt.code"; then
    echo "package test: the $run run exited $(cat "$scratch/$run.txt.code"), smcbip simulate" \
         "$(cat "$scratch/expected.txt.code")" >&2
    status=1
  fi
done

# The consumer's build ran the installed bipc (smcbip::bipc_tool) for the model's outline.
"$bipc" ir "$model" --root "$root" >"$scratch/outline.txt"
if ! diff -u "$scratch/outline.txt" "$consumer_build/model_outline.txt" >&2; then
  echo "package test: the outline written by smcbip::bipc_tool differs from bipc ir" >&2
  status=1
fi

[[ $status -eq 0 ]] || fail "outputs differ (files in $scratch)"
# The prefix and the consumer's build are some hundreds of megabytes; the logs stay.
rm -rf "$prefix" "$consumer_build"
echo "package test: installed, built against; consumer, plugin and installed smcbip match" \
     "smcbip simulate ($(wc -l <"$scratch/expected.txt") lines," \
     "exit $(cat "$scratch/expected.txt.code"))"
