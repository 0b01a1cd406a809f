#!/usr/bin/env bash
# smcbip explore's and check's files: the plot is well-formed SVG with one marker per point and
# a band per curve, the CSV has a row per point, a refused command writes neither, and the traces
# --save-traces keeps are the runs the answer counted (smcbip monitor judges them the same).
#
# Usage: explore_outputs.sh BIN_DIR SOURCE_DIR
set -euo pipefail

bin=$1
source=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

cat >"$out/sweep.mtl" <<'MTL'
param t = 0:100:10
param k = {2, 3}
P=? [ F[0,t] Channel.id_channel > k ]
P>=0.5 [ F[0,100] Channel.id_channel >= k ]
MTL

"$bin/smcbip" explore "$source/models/channel.bip" "$out/sweep.mtl" --root 'System()' \
  --delta 0.05 --plot "$out/sweep.svg" --csv "$out/sweep.csv" --json >"$out/stdout.json"

python3 - "$out" <<'PY'
import csv, json, sys, xml.etree.ElementTree as ET
out = sys.argv[1]
ns = {"s": "http://www.w3.org/2000/svg"}
svg = ET.parse(f"{out}/sweep.svg").getroot()
panels = svg.findall("s:g", ns)
assert len(panels) == 2, f"{len(panels)} panels"
# First query: 11 values of t for each of 2 values of k; second: 2 values of k.
circles = [len(p.findall("s:circle", ns)) for p in panels]
assert circles == [22, 2], circles
bands = [len(p.findall("s:polygon", ns)) for p in panels]
assert bands == [2, 0], bands  # a test (SPRT) has no interval to shade
dashed = [l for l in panels[1].findall("s:line", ns) if l.get("stroke-dasharray")]
assert len(dashed) == 1, "the second panel has one threshold line"
rows = list(csv.DictReader(open(f"{out}/sweep.csv")))
assert len(rows) == 24, len(rows)
assert rows[0]["query"] == "P=? [ F[0,t] (Channel.id_channel > k) ]", rows[0]["query"]
assert {r["method"] for r in rows} == {"pestim", "sprt"}, {r["method"] for r in rows}
report = json.load(open(f"{out}/stdout.json"))
assert len(report["results"]) == 24
assert len(report["model"]["hash"]) == 64, report["model"]
for r, row in zip(report["results"], rows):
    assert abs(float(row["estimate"]) - r["estimate"]) < 1e-12
PY

# A refused command leaves no file behind.
if "$bin/smcbip" explore "$source/models/channel.bip" "$out/sweep.mtl" --root 'System()' \
  --plot "$out/failed.svg" --max-steps 0 2>/dev/null; then
  echo "explore_outputs: --max-steps 0 was accepted" >&2
  exit 1
fi
[[ ! -e $out/failed.svg ]] || { echo "explore_outputs: a failed run wrote its plot" >&2; exit 1; }
# Every run an estimate took is kept, and judged again from its trace it counts the same.
printf 'P=? [ F[0,100] Channel.lost > 0 ]\n' >"$out/one.mtl"
"$bin/smcbip" check "$source/models/channel.bip" "$out/one.mtl" --root 'System()' --delta 0.1 \
  --save-traces "$out/traces" --json >"$out/check.json"
# --trace takes one file per use (it never swallows the arguments after it).
traces=()
for trace in "$out"/traces/*.jsonl; do traces+=(--trace "$trace"); done
"$bin/smcbip" monitor "$out/one.mtl" "${traces[@]}" \
  --model "$source/models/channel.bip" --root 'System()' --json >"$out/monitor.json" ||
  [[ $? -eq 1 ]] # some runs are false
python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
answer = json.load(open(f"{out}/check.json"))["results"][0]
verdicts = [r["verdict"] for r in json.load(open(f"{out}/monitor.json"))["results"]]
assert len(verdicts) == answer["samples"], (len(verdicts), answer["samples"])
assert abs(verdicts.count(True) / len(verdicts) - answer["estimate"]) < 1e-12
PY
echo "explore_outputs: ok"
