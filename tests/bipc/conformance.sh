#!/usr/bin/env bash
# Runs 'bipc check' over the reference engine's conformance models and the ESROCOS watchdog model.
#
# Usage: conformance.sh BIN_DIR
#
# Every model is checked twice: without a root (types only) and with the root its original test
# used (EXPECTED.md, sections 5 and 11; conformance_roots.txt lists them). Each run must exit 0,
# except the three models the reference compiler rejects for an unguarded priority cycle, which
# must exit 2 and say "cycle".
# Shared data root: $SMCBIP_SHARED_DATA, by default <repository root>/../shared/data. Without it
# the script prints one line and exits 77 (CTest SKIP_RETURN_CODE).
#
# Exit status: 0 all runs as expected, 1 some run not (each is listed with its stderr), 77 skipped.

set -u

readonly TIMEOUT_SECONDS=60
readonly MAX_SHOWN_LINES=30

if [[ $# -ne 1 ]]; then
  echo "usage: conformance.sh BIN_DIR" >&2
  exit 1
fi
bipc=$1/bipc
if [[ ! -x $bipc ]]; then
  echo "conformance: no executable bipc in $1" >&2
  exit 1
fi

script_dir=$(cd -- "$(dirname -- "${BASH_SOURCE[0]}")" && pwd)
repo_root=$(cd -- "$script_dir/../.." && pwd)
shared_data=${SMCBIP_SHARED_DATA:-$repo_root/../shared/data}
conformance_dir=$shared_data/bip-conformance
esrocos_dir=$shared_data/esrocos-mc_watchdog/BipModel/sources

for required in "$conformance_dir" "$esrocos_dir"; do
  if [[ ! -d $required ]]; then
    echo "skipping: shared conformance data not found at $required"
    exit 77
  fi
done

# Root of each model, as its original test instantiated it: one 'KEY ROOT' a line.
declare -A roots=()
while read -r key root; do
  [[ -z $key || $key == \#* ]] && continue
  roots[$key]=$root
done < "$script_dir/conformance_roots.txt"
if [[ ${#roots[@]} -eq 0 ]]; then
  echo "conformance: no roots read from $script_dir/conformance_roots.txt" >&2
  exit 1
fi

# Packages that only serve other models: checked without a root.
declare -A helper_packages=(
  [compile_only/nested_pack]=1
  [compile_only/nested/pack]=1
)

# Models the reference compiler rejects (unguarded priority cycles): exit 2, reason "cycle".
declare -A rejected=(
  [running/priority_rules_cycle2]=1
  [compile_only/priority_rules_atom_cycle]=1
  [compile_only/priority_rules_atom_cycle2]=1
)

work_dir=$(mktemp -d "${TMPDIR:-/tmp}/conformance.XXXXXX") || exit 1
trap 'rm -rf -- "$work_dir"' EXIT
report=$work_dir/report
: > "$report"

passed=0
failed=0

# run_check LABEL EXPECTED_EXIT REQUIRED_STDERR_TEXT ARG... : runs 'bipc check ARG...'.
run_check() {
  local label=$1 expected=$2 required_text=$3
  shift 3
  local stdout_file=$work_dir/stdout stderr_file=$work_dir/stderr actual problem=""
  timeout "$TIMEOUT_SECONDS" "$bipc" check "$@" > "$stdout_file" 2> "$stderr_file" < /dev/null
  actual=$?
  if [[ $actual -eq 124 ]]; then
    problem="timed out after ${TIMEOUT_SECONDS}s"
  elif [[ $actual -ne $expected ]]; then
    problem="exit status: expected $expected, got $actual"
  elif [[ -n $required_text ]] && ! grep -qi -- "$required_text" "$stderr_file"; then
    problem="stderr does not mention '$required_text'"
  fi
  if [[ -z $problem ]]; then
    passed=$((passed + 1))
    return
  fi
  failed=$((failed + 1))
  local total
  total=$(wc -l < "$stderr_file")
  {
    echo "FAIL $label"
    echo "    command: bipc check $(printf '%q ' "$@")"
    echo "    $problem"
    head -n "$MAX_SHOWN_LINES" -- "$stderr_file" | sed 's/^/    | /'
    if [[ $total -gt $MAX_SHOWN_LINES ]]; then
      echo "    | ... ($((total - MAX_SHOWN_LINES)) more lines)"
    fi
  } >> "$report"
}

# check_model KEY FILE INCLUDE_DIR ROOT : one run without root, one with ROOT (if not empty).
check_model() {
  local key=$1 file=$2 include_dir=$3 root=$4 expected=0 required_text=""
  if [[ -n ${rejected[$key]+set} ]]; then
    expected=2
    required_text=cycle
  fi
  run_check "$key (no root)" "$expected" "$required_text" "$file" -I "$include_dir"
  if [[ -n $root ]]; then
    run_check "$key --root '$root'" "$expected" "$required_text" \
      "$file" --root "$root" -I "$include_dir"
  fi
}

model_count=0
for folder in running compile_only running_multithread_extra; do
  for file in "$conformance_dir/$folder"/*.bip; do
    [[ -e $file ]] || continue
    key=$folder/$(basename -- "$file" .bip)
    model_count=$((model_count + 1))
    if [[ -n ${roots[$key]+set} ]]; then
      check_model "$key" "$file" "$conformance_dir/$folder" "${roots[$key]}"
    elif [[ -n ${helper_packages[$key]+set} ]]; then
      check_model "$key" "$file" "$conformance_dir/$folder" ""
    else
      failed=$((failed + 1))
      echo "FAIL $key: model missing from the root table of conformance.sh" >> "$report"
    fi
  done
done

nested_helper=$conformance_dir/compile_only/nested/pack.bip
if [[ -f $nested_helper ]]; then
  model_count=$((model_count + 1))
  check_model compile_only/nested/pack "$nested_helper" "$conformance_dir/compile_only" ""
fi

for file in "$esrocos_dir"/*.bip; do
  [[ -e $file ]] || continue
  model_count=$((model_count + 1))
  check_model "esrocos/$(basename -- "$file" .bip)" "$file" "$esrocos_dir" 'Syst()'
done

cat "$report"
echo "conformance: $model_count models, $passed runs passed, $failed failed"
if [[ $failed -ne 0 ]]; then
  exit 1
fi
exit 0
