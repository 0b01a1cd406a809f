#!/usr/bin/env bash
# Runs 'bipc check' over the reference engine's conformance models and the ESROCOS watchdog model.
#
# Usage: conformance.sh BIN_DIR
#
# Every model is checked twice: without a root (types only) and with the root its original test
# used (EXPECTED.md, sections 5 and 11). Each run must exit 0, except the three models the
# reference compiler rejects for an unguarded priority cycle, which must exit 2 and say "cycle".
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

# Root of each model, as its original test instantiated it (EXPECTED.md sections 5 and 11).
declare -A roots=(
  [compile_only/atom_port_values]='CT()'
  [compile_only/broadcast_reverted]='MyCompoundType()'
  [compile_only/conflict_component_prio]='Comp()'
  [compile_only/conflict_packages]='Composite()'
  [compile_only/conflict_packages2]='Composite()'
  [compile_only/conflict_type_instance]='Comp()'
  [compile_only/const_data]='CT()'
  [compile_only/hierarchy]='MyCompound()'
  [compile_only/internal_port]='MyCompound()'
  [compile_only/modulo8]='Modulo8()'
  [compile_only/periodic_tick]='MyCompound()'
  [compile_only/priorities_atom]='MyCompound()'
  [compile_only/priorities_wildcard]='MyCompound()'
  [compile_only/priority_rules_atom_cycle]='MyCompoundType()'
  [compile_only/priority_rules_atom_cycle2]='MyCompoundType()'
  [compile_only/tempcontrol]='Top()'
  [running/and_expressions]='AndExpressions()'
  [running/atom_internal_transitions]='CT()'
  [running/broadcast]='MyCompoundType()'
  [running/broadcast_browser]='MyCompoundType()'
  [running/broadcast_maximal]='MyCompoundType()'
  [running/broadcast_reverted]='MyCompoundType()'
  [running/broadcast_up]='MyCompoundType()'
  [running/broadcast_up_down]='MyCompoundType()'
  [running/clock_speed]='Compound()'
  [running/clock_units]='Compound()'
  [running/const_data]='Top()'
  [running/cyclic]='CT()'
  [running/demosaicing9]='Demosaicer()'
  [running/dining_philo]='DiningPhilo()'
  [running/dining_philo_flat]='DiningPhilo()'
  [running/double_compound]='System()'
  [running/doublecounter]='CT()'
  [running/doublecounter2]='CT()'
  [running/external]='Compound()'
  [running/external_error]='Compound()'
  [running/guarded_transitions]='MyCompoundType()'
  [running/hierarch_priority]='MyCompoundType()'
  [running/hierarchical]='MyCompoundType()'
  [running/internal_export_compound]='BIG_CT()'
  [running/invariants]='CT()'
  [running/invariants2]='CT()'
  [running/maximal_progress]='Top()'
  [running/maximal_progress_hierarchy]='System()'
  [running/multi_export_atom]='MyCompoundType()'
  [running/multi_export_compound]='Top()'
  [running/multi_export_compound2]='Top()'
  [running/nested]='MyCompoundType()'
  [running/nested2]='MyCompoundType()'
  [running/nested3]='MyCompoundType()'
  [running/or_expressions]='OrExpressions()'
  [running/petri_net]='MyCompoundType()'
  [running/petri_net_deterministic]='MyCompoundType()'
  [running/petri_net_non_deterministic]='MyCompoundType()'
  [running/petri_net_non_deterministic2]='MyCompoundType()'
  [running/petri_net_non_deterministic3]='MyCompoundType()'
  [running/petri_net_non_safe]='MyCompoundType()'
  [running/priority_rules]='MyCompoundType()'
  [running/priority_rules_atom]='MyCompoundType()'
  [running/priority_rules_atom_closure]='MyCompoundType()'
  [running/priority_rules_atom_cycle3]='MyCompoundType()'
  [running/priority_rules_atom_cycle4]='MyCompoundType()'
  [running/priority_rules_atom_export]='MyCompoundType()'
  [running/priority_rules_atom_internal]='MyCompoundType()'
  [running/priority_rules_atom_wildcard]='MyCompoundType()'
  [running/priority_rules_cycle]='MyCompoundType()'
  [running/priority_rules_cycle2]='MyCompoundType()'
  [running/priority_rules_cycle3]='MyCompoundType()'
  [running/priority_rules_cycle_hierarchy]='CTH()'
  [running/priority_rules_guard]='MyCompoundType()'
  [running/priority_rules_guard_external]='EvilPriorityRules()'
  [running/priority_rules_no_cycle]='MyCompoundType()'
  [running/priority_rules_no_cycle2]='MyCompoundType()'
  [running/priority_rules_wildcard]='MyCompoundType()'
  [running/rendezvous_down]='MyCompoundType()'
  [running/simple10counter]='CT()'
  [running/test_resume]='Compound()'
  [running/test_resume2]='Compound()'
  [running/test_resume3]='Compound()'
  [running/test_resume3_error]='Compound()'
  [running/test_resume4]='Compound()'
  [running/test_resume4_error]='Compound()'
  [running/test_resume_deadlock]='Compound()'
  [running/test_resume_error]='Compound()'
  [running/time_lock1]='Compound()'
  [running/time_lock2]='Compound()'
  [running/time_lock3]='Compound()'
  [running/timed_tempcontrol]='Top()'
  [running/writers_buffer]='Compound()'
  [running_multithread_extra/conflicting]='Comp()'
  [running_multithread_extra/non_conflicting]='Comp()'
  [running_multithread_extra/priority_rules_cycle4]='Compound()'
  [running_multithread_extra/priority_rules_cycle5]='Level1()'
  [running_multithread_extra/priority_rules_no_cycle3]='MyCompoundType()'
  [running_multithread_extra/priority_rules_no_cycle4]='Compound()'
  [running_multithread_extra/tempcontrol]='Top()'
)

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
