#!/usr/bin/env bash
# Runs one golden design of taste2bip: translates the design of CASE_DIR, compares the outline of
# the BIP it makes (bipc ir) with CASE_DIR/outline.txt, then checks CASE_DIR/properties.mtl, a
# self-describing golden file of tests/run_golden.sh whose %d is the folder holding `out/`, the
# translation (so its COMMAND reads `smcbip check %d/out/taste.bip %s ...`).
#
# Usage: golden_case.sh BIN_DIR CASE_DIR
#
# CASE_DIR holds the design (interfaceview.xml or InterfaceView.aadl, .asn files, <function>.pr
# files), optionally taste2bip.args (more arguments of taste2bip, one line, %d for CASE_DIR),
# outline.txt and
# properties.mtl. Exit status 0 when everything matches, 1 otherwise.

set -u

[[ $# -eq 2 ]] || { echo "usage: golden_case.sh BIN_DIR CASE_DIR" >&2; exit 1; }
bin_dir=$1
case_dir=$2
here=$(cd -- "$(dirname -- "$0")" && pwd)

view=$case_dir/interfaceview.xml
[[ -f $view ]] || view=$case_dir/InterfaceView.aadl
[[ -f $view ]] || { echo "FAIL $case_dir: no interface view"; exit 1; }
extra=()
if [[ -f $case_dir/taste2bip.args ]]; then
  read -r -a extra < "$case_dir/taste2bip.args"
  extra=("${extra[@]//%d/$case_dir}")
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/taste2bip_golden.XXXXXX") || exit 1
trap 'rm -rf -- "$work"' EXIT

if ! "$bin_dir/taste2bip" "$view" "${extra[@]+"${extra[@]}"}" -o "$work/out" > "$work/report" \
    2> "$work/stderr"; then
  echo "FAIL $case_dir: taste2bip failed"
  sed 's/^/+ /' "$work/stderr"
  exit 1
fi

"$bin_dir/bipc" ir "$work/out/taste.bip" --root 'Syst()' > "$work/outline" 2>&1
if ! diff -u "$case_dir/outline.txt" "$work/outline" > "$work/outline.diff"; then
  echo "FAIL $case_dir: the outline differs from outline.txt"
  cat "$work/outline.diff"
  exit 1
fi

cp -- "$case_dir/properties.mtl" "$work/properties.mtl"
bash "$here/../run_golden.sh" "$bin_dir" "$work/properties.mtl" || {
  echo "FAIL $case_dir: its properties (report below)"
  sed 's/^/+ /' "$work/report"
  exit 1
}
echo "PASS $case_dir"
