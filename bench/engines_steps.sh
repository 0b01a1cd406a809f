#!/usr/bin/env bash
# Whole-run simulation speed: steps per second of the reference, optimised and multithread engines.
#
# Usage: bench/engines_steps.sh [BUILD_DIR]   (default: build)
# Runs `smcbip simulate --silent --limit K` on generated rendezvous and broadcast models of 10 to
# 10,000 atoms, on the work family (100 atoms, WORK assignments per transition) and on
# models/channel.bip, and prints steps per second from the wall time (minus that of a 1-step run,
# which is process start and model loading; K chosen per engine for runs of about a second; the
# steps column is the reference engine's K), each engine also as a ratio against the reference
# engine in the same invocation, beside the targets. It reports only:
# timings on a shared machine are noisy (the load average is printed), so it never fails on them.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
build_dir=${1:-build}
smcbip="$build_dir/bin/smcbip"
generator="$build_dir/bin/gen_bip_models"
models_dir="$build_dir/bench-models"
sizes=(10 100 1000 10000)
runs=${RUNS:-3}
target_seconds=${TARGET_SECONDS:-1.0}
work=${WORK:-5000}
threads=${THREADS:-2}

for tool in "$smcbip" "$generator"; do
  if [[ ! -x "$tool" ]]; then
    echo "engines_steps: $tool not found; build first (make build)" >&2
    exit 2
  fi
done
mkdir -p "$models_dir"

source "bench/steps_common.sh"

# As steps_per_second, with a step count chosen for this engine (a faster engine runs more
# steps, so that its time is not lost in the noise of start-up).
engine_steps_per_second() {
  local model=$1 limit
  shift
  limit=$(choose_limit "$model" 'Top()' "$@") || return 1
  steps_per_second "$model" 'Top()' "$limit" "$@"
}

echo "engines_steps: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg);" \
  "multithread on $threads threads; best of $runs runs"
printf '%-10s %6s %9s %13s %13s %13s %8s %8s\n' family atoms steps 'ref steps/s' \
  'opt steps/s' 'mt steps/s' 'opt/ref' 'mt/ref'
# family atoms -> "ref opt mt" steps per second, for the targets below.
declare -A figures
measure() {
  local family=$1 n=$2 model=$3 limit ref opt mt
  if ! limit=$(choose_limit "$model" 'Top()' 2>"$models_dir/measure.err"); then
    printf '%-10s %6d  not run: %s\n' "$family" "$n" \
      "$(grep -m1 'error' "$models_dir/measure.err" || echo 'smcbip failed')"
    return 0
  fi
  ref=$(steps_per_second "$model" 'Top()' "$limit" --engine reference) || return 1
  opt=$(engine_steps_per_second "$model" --engine optimised) || return 1
  mt=$(engine_steps_per_second "$model" --engine multithread --threads "$threads") || return 1
  figures["$family $n"]="$ref $opt $mt"
  printf '%-10s %6d %9d %13d %13d %13d %8s %8s\n' "$family" "$n" "$limit" "$ref" "$opt" "$mt" \
    "$(ratio "$opt" "$ref")" "$(ratio "$mt" "$ref")"
}

for family in rendezvous broadcast; do
  for n in "${sizes[@]}"; do
    model="$models_dir/${family}_$n.bip"
    "$generator" --family "$family" --atoms "$n" -o "$model"
    measure "$family" "$n" "$model"
  done
done
model="$models_dir/work_100.bip"
"$generator" --family work --atoms 100 --work "$work" -o "$model"
measure work 100 "$model"

# The stochastic Channel model (interpreted), on the reference and the optimised engine.
channel_limit=$(choose_limit models/channel.bip 'System()')
channel_ref=$(steps_per_second models/channel.bip 'System()' "$channel_limit" --engine reference)
channel_opt_limit=$(choose_limit models/channel.bip 'System()' --engine optimised)
channel=$(steps_per_second models/channel.bip 'System()' "$channel_opt_limit" --engine optimised)
printf '%-10s %6s %9d %13d %13d %13s %8s\n' channel 3 "$channel_limit" "$channel_ref" "$channel" \
  - "$(ratio "$channel" "$channel_ref")"

echo
echo "targets (reported, not enforced):"
read -r ref opt _ <<<"${figures[rendezvous 1000]:-0 0 0}"
echo "  optimised >= 10x reference on rendezvous, 1000 atoms: $(ratio "$opt" "$ref")x"
read -r _ opt mt <<<"${figures[work 100]:-0 0 0}"
echo "  multithread >= 1.5x optimised on work, 100 atoms ($work assignments per transition," \
  "$threads threads): $(ratio "$mt" "$opt")x"
echo "  channel >= 2000000 steps/s per core (optimised engine): $channel steps/s"
