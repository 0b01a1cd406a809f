#!/usr/bin/env bash
# Generates the C++ of every conformance model (bipc gen) for the typed conformance suite's
# generated-model variants, and the sources that compile and register it.
#
# Usage: generate_conformance.sh BIN_DIR OUT_DIR CHUNKS
#
# For each model of bip-conformance with a root in tests/bipc/conformance.sh's table (except the
# ones the reference compiler rejects), writes OUT_DIR/models/<n>/model_code.{h,cpp} in namespace
# generated_conformance::m<n>; then OUT_DIR/chunk_<k>.cpp for k < CHUNKS, each including a share of
# the generated sources, and OUT_DIR/registry.cpp, the table (model, root, factory) that
# tests/engines/generated_conformance.h declares. Without the shared data (see conformance.sh)
# the chunks and the table are empty, and the suite's generated variants skip. A model that
# bipc gen refuses is reported on stderr and left out: the tests that need it then fail.
set -u

if [[ $# -ne 3 ]]; then
  echo "usage: generate_conformance.sh BIN_DIR OUT_DIR CHUNKS" >&2
  exit 1
fi
bipc=$1/bipc
out=$2
chunks=$3

script_dir=$(cd -- "$(dirname -- "${BASH_SOURCE[0]}")" && pwd)
repo_root=$(cd -- "$script_dir/../.." && pwd)
shared_data=${SMCBIP_SHARED_DATA:-$repo_root/../shared/data}
conformance_dir=$shared_data/bip-conformance
table=$repo_root/tests/bipc/conformance.sh

eval "$(sed -n '/^declare -A roots=(/,/^)/p' "$table")"
eval "$(sed -n '/^declare -A rejected=(/,/^)/p' "$table")"

mkdir -p "$out/models"
declarations=""
entries=""
sources=()
n=0
if [[ -d $conformance_dir ]]; then
  for key in $(printf '%s\n' "${!roots[@]}" | sort); do
    [[ -n ${rejected[$key]+set} ]] && continue
    file=$conformance_dir/$key.bip
    [[ -f $file ]] || continue
    root=${roots[$key]}
    dir=$out/models/$n
    if ! "$bipc" gen --code-only "$file" --root "$root" -I "$(dirname -- "$file")" -o "$dir" \
      --namespace "generated_conformance::m$n" 2> "$dir.err"; then
      echo "generate_conformance: bipc gen refused $key --root '$root':" >&2
      cat "$dir.err" >&2
      n=$((n + 1))
      continue
    fi
    sources+=("$dir/model_code.cpp")
    declarations+="namespace generated_conformance::m$n {
std::unique_ptr<smcbip::engines::ModelCode> make_model_code(
    const smcbip::bipc::ir::System&, const smcbip::engines::BoundFunctions&,
    smcbip::engines::CallContext&, const smcbip::engines::GuardBounds*);
}
"
    entries+="      {\"$key\", \"${root//\"/\\\"}\", &generated_conformance::m$n::make_model_code},
"
    n=$((n + 1))
  done
fi

# Written through temporary files, so that an interrupted run leaves no half table behind.
write() {
  printf '%s' "$2" > "$1.tmp" && mv -f "$1.tmp" "$1"
}

for ((k = 0; k < chunks; ++k)); do
  text="// Generated conformance models, share $k of $chunks (generate_conformance.sh).
"
  for ((i = k; i < ${#sources[@]}; i += chunks)); do
    text+="#include \"${sources[$i]}\"
"
  done
  write "$out/chunk_$k.cpp" "$text"
done

write "$out/registry.cpp" "// The generated conformance models (generate_conformance.sh).
#include \"tests/engines/generated_conformance.h\"

#include <memory>

#include \"engines/interpreter/code_eval.h\"

$declarations
namespace smcbip::tests {

const std::vector<GeneratedConformanceModel>& generated_conformance_models() {
  static const std::vector<GeneratedConformanceModel> models = {
$entries  };
  return models;
}

}  // namespace smcbip::tests
"
echo "generate_conformance: ${#sources[@]} models generated"
