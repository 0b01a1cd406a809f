#!/usr/bin/env bash
# Makes the seeds of the fuzzers that are not files of the tree, from the bundled models: their
# IR encodings (CBOR and JSON) and JSON-lines traces of short runs; and gathers the property
# files of the tree in one folder.
#
# Usage: fuzz_seeds.sh BUILD_DIR OUT_DIR   (BUILD_DIR's tools write OUT_DIR/{ir,traces,properties})
set -euo pipefail

[[ $# -eq 2 ]] || { echo "usage: fuzz_seeds.sh BUILD_DIR OUT_DIR" >&2; exit 1; }
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=$(realpath "$1")
out=$(realpath -m "$2")

models=(models/*.bip models/families/*.bip)
mkdir -p "$out/ir" "$out/traces" "$out/properties"

"$build/bin/bipc_ir_seeds" "$out/ir" "${models[@]}" >/dev/null

for model in "${models[@]}"; do
  name=$(basename "$model" .bip)
  root=()
  [[ $model == models/families/* ]] && root=(--root 'Top()')
  for seed in 1 2; do
    # A run that ends in an error still writes its trace, a useful seed as well.
    "$build/bin/smcbip" simulate "$model" "${root[@]}" --seed "$seed" --limit 30 \
      --trace jsonl >"$out/traces/$name-$seed.jsonl" 2>/dev/null || true
  done
done

# Named after their paths, as some share a name.
for file in models/*.mtl tests/smc/golden/*.mtl tests/monitors/properties/*/*.mtl; do
  cp "$file" "$out/properties/${file//\//_}"
done
echo "fuzz_seeds: $(ls "$out/ir" | wc -l) IR encodings, $(ls "$out/traces" | wc -l)" \
  "traces, $(ls "$out/properties" | wc -l) property files in $out"
