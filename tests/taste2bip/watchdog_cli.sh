#!/usr/bin/env bash
# The watchdog's nominal properties from the command line: taste2bip translates the ESROCOS
# watchdog design with the original's hand-written Watchdog (--atom), and `smcbip check` answers
# watchdog/watchdog_translation_nominal.mtl on the package written: no stop is sent (0) and every
# command reaches the motors within its deadline (1), each estimate within delta = 0.02.
# Usage: watchdog_cli.sh BIN_DIR SOURCE_DIR
# Shared data root: $SMCBIP_SHARED_DATA, by default SOURCE_DIR/../shared/data; without it the
# script prints one line and exits 77 (CTest SKIP_RETURN_CODE).
set -u
bin=$1
source_dir=$2
data=${SMCBIP_SHARED_DATA:-$source_dir/../shared/data}/esrocos-mc_watchdog
if [[ ! -d $data ]]; then
  echo "watchdog_cli: the shared ESROCOS watchdog data is absent"
  exit 77
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/watchdog_cli.XXXXXX") || exit 1
trap 'rm -rf -- "$work"' EXIT
props=$source_dir/tests/taste2bip/watchdog

if ! "$bin/taste2bip" "$data/TasteModel/InterfaceView.aadl" \
  --atom "Watchdog=$props/watchdog_atom.bip" -o "$work/out" > "$work/translate.log" 2>&1; then
  echo "FAIL: taste2bip:"
  cat "$work/translate.log"
  exit 1
fi
if ! "$bin/smcbip" check "$work/out/taste.bip" "$props/watchdog_translation_nominal.mtl" \
  --root 'Syst()' --seed 20261130 --delta 0.02 --alpha 0.01 > "$work/check.log" 2>&1; then
  echo "FAIL: smcbip check:"
  cat "$work/check.log"
  exit 1
fi
cat "$work/check.log"
# The two answers, in the file's order: estimate 0 (no stop), then 1 (deadline met).
mapfile -t estimates < <(sed -n 's/^ *pestim: estimate \([0-9.e-]*\) in .*/\1/p' "$work/check.log")
if [[ ${#estimates[@]} -ne 2 ]] ||
  ! awk -v a="${estimates[0]}" -v b="${estimates[1]}" 'BEGIN { exit !(a <= 0.02 && b >= 0.98) }'; then
  echo "FAIL: expected the estimates 0 and 1 (within 0.02), got: ${estimates[*]:-none}"
  exit 1
fi
echo "watchdog_cli: ok"
