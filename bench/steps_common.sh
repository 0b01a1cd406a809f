# Timing helpers of the whole-run benchmarks (sourced): they use $smcbip, $models_dir, $runs and
# $target_seconds from the script that sources them.

# Wall seconds of one silent run of model $1 (root $2; a folder: its compiled plugin, through
# --compiled) with $3 steps and engine options $4...
run_seconds() {
  local model=$1 root=$2 limit=$3 start end
  shift 3
  local -a target=("$model" --root "$root")
  [[ -d $model ]] && target=(--compiled "$model")
  start=$EPOCHREALTIME
  if ! "$smcbip" simulate "${target[@]}" --seed 1 --limit "$limit" --silent "$@" \
    >/dev/null 2>"$models_dir/last.err"; then
    echo "$(basename "$0"): smcbip simulate failed on $model $*:" >&2
    head -n 20 "$models_dir/last.err" >&2
    return 1
  fi
  end=$EPOCHREALTIME
  awk -v s="$start" -v e="$end" 'BEGIN { printf "%.6f\n", e - s }'
}

# Steps per run such that the engine (options $3...) takes about target_seconds beyond start-up: the
# start-up is a run of 1 step; probes of 4 times more steps until one takes a tenth of the
# target; then scaled. At least 100 steps, at most 50 million.
choose_limit() {
  local model=$1 root=$2 start_up probe=100 seconds
  shift 2
  start_up=$(run_seconds "$model" "$root" 1 "$@") || return 1
  for (( ; ; probe *= 4)); do
    seconds=$(run_seconds "$model" "$root" "$probe" "$@") || return 1
    if awk -v s="$seconds" -v a="$start_up" -v t="$target_seconds" -v p="$probe" \
      'BEGIN { exit !(s - a >= t / 10 || p >= 5e7) }'; then
      break
    fi
  done
  awk -v s="$seconds" -v a="$start_up" -v p="$probe" -v t="$target_seconds" 'BEGIN {
    d = s - a; k = (d > 0 ? p * t / d : p); if (k < 100) k = 100; if (k > 5e7) k = 5e7
    printf "%d\n", k }'
}

# Best wall seconds of `runs` runs with $3 steps.
best_seconds() {
  local model=$1 root=$2 limit=$3 best="" seconds r
  shift 3
  for ((r = 0; r < runs; r++)); do
    seconds=$(run_seconds "$model" "$root" "$limit" "$@") || return 1
    if [[ -z "$best" ]] || awk -v a="$seconds" -v b="$best" 'BEGIN { exit !(a < b) }'; then
      best=$seconds
    fi
  done
  echo "$best"
}

# Steps per second of the simulation itself: the best run's time minus the best time of a
# 1-step run with the same engine (process start and model loading), so that loading a large
# model does not hide the speed of its steps.
steps_per_second() {
  local model=$1 root=$2 limit=$3 full start_up
  shift 3
  full=$(best_seconds "$model" "$root" "$limit" "$@") || return 1
  start_up=$(best_seconds "$model" "$root" 1 "$@") || return 1
  awk -v k="$limit" -v s="$full" -v a="$start_up" \
    'BEGIN { d = s - a; printf "%.0f\n", (d > 0 ? (k - 1) / d : 0) }'
}

ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", (b > 0 ? a / b : 0) }'; }
