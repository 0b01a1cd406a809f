#!/usr/bin/env bash
# Generated against interpreted models: steps per second of the optimised engine running a model
# interpreted from its IR and running the C++ that bipc gen made of it (smcbip --compiled), in
# the same invocation, on the rendezvous and broadcast families (10 to 10,000 atoms), the work
# family and models/channel.bip (stochastic).
#
# Usage: bench/generated_steps.sh [BUILD_DIR]   (default: build)
# The build is installed into BUILD_DIR/bench-prefix, each model is generated into
# BUILD_DIR/bench-generated/<model> and its plugin built there (Release) against that install.
# Steps per second are measured as by bench/engines_steps.sh (whole runs minus start-up, best of
# RUNS). It reports, never fails on timings: a shared machine's are noisy (load printed).
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
build_dir=${1:-build}
smcbip="$build_dir/bin/smcbip"
bipc="$build_dir/bin/bipc"
generator="$build_dir/bin/gen_bip_models"
models_dir="$build_dir/bench-models"
generated_dir="$build_dir/bench-generated"
prefix="$(cd "$build_dir" && pwd)/bench-prefix"
sizes=(${SIZES:-10 100 1000 10000})
runs=${RUNS:-3}
target_seconds=${TARGET_SECONDS:-1.0}
# The work family's generated code is straight-line C++ of WORK statements per action, which the
# compiler takes minutes over at 5,000 (engines_steps.sh's default): 1,000 keep the work the
# larger part of a step at a fraction of the build.
work=${WORK:-1000}

for tool in "$smcbip" "$bipc" "$generator"; do
  if [[ ! -x "$tool" ]]; then
    echo "generated_steps: $tool not found; build first (make build)" >&2
    exit 2
  fi
done
mkdir -p "$models_dir" "$generated_dir"
source "bench/steps_common.sh"

cmake --install "$build_dir" --prefix "$prefix" >"$generated_dir/install.log"
compiler=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build_dir/CMakeCache.txt")

# The plugin of model $1 (root $2) built in $generated_dir/$3.
build_plugin() {
  local model=$1 root=$2 name=$3 dir="$generated_dir/$3"
  "$bipc" gen "$model" --root "$root" -o "$dir" --namespace "bench_$name" --no-main \
    2>"$dir.log" || { cat "$dir.log" >&2; return 1; }
  cmake -S "$dir" -B "$dir/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_CXX_COMPILER="$compiler" >>"$dir.log" 2>&1 &&
    cmake --build "$dir/build" --target "bench_${name}_plugin" -j2 >>"$dir.log" 2>&1 ||
    { tail -n 30 "$dir.log" >&2; return 1; }
}

echo "generated_steps: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg);" \
  "optimised engine; best of $runs runs"
printf '%-10s %6s %16s %16s %8s\n' family atoms 'interpreted/s' 'generated/s' ratio
declare -A figures
measure() {
  local family=$1 n=$2 model=$3 root=$4 name="${1}_$2" interpreted generated limit
  build_plugin "$model" "$root" "$name" || return 1
  limit=$(choose_limit "$model" "$root" --engine optimised) || return 1
  interpreted=$(steps_per_second "$model" "$root" "$limit" --engine optimised) || return 1
  limit=$(choose_limit "$generated_dir/$name" "$root" --engine optimised) || return 1
  generated=$(steps_per_second "$generated_dir/$name" "$root" "$limit" --engine optimised) ||
    return 1
  figures["$family $n"]="$interpreted $generated"
  printf '%-10s %6s %16d %16d %8s\n' "$family" "$n" "$interpreted" "$generated" \
    "$(ratio "$generated" "$interpreted")"
}

for family in rendezvous broadcast; do
  for n in "${sizes[@]}"; do
    model="$models_dir/${family}_$n.bip"
    "$generator" --family "$family" --atoms "$n" -o "$model"
    measure "$family" "$n" "$model" 'Top()'
  done
done
model="$models_dir/work_100.bip"
"$generator" --family work --atoms 100 --work "$work" -o "$model"
measure work 100 "$model" 'Top()'
measure channel 3 models/channel.bip 'System()'

echo
echo "targets (reported, not enforced):"
worst=""
for key in "${!figures[@]}"; do
  read -r interpreted generated <<<"${figures[$key]}"
  r=$(ratio "$generated" "$interpreted")
  if [[ -z $worst ]] || awk -v a="$r" -v b="${worst%% *}" 'BEGIN { exit !(a < b) }'; then
    worst="$r ($key)"
  fi
done
echo "  generated >= 3x interpreted on every model: lowest ratio $worst"
read -r _ generated <<<"${figures[channel 3]:-0 0}"
echo "  channel generated >= 5000000 stochastic steps/s per core: $generated steps/s"
