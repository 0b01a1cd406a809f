#!/usr/bin/env bash
# Text that is not UTF-8: a string literal holding a Latin-1 byte is an error at its position
# (exit 2, nothing on stdout), and check's JSON names a model file whose name holds such a byte
# with U+FFFD in its place rather than failing.
#
# Usage: non_utf8_text.sh BIN_DIR SOURCE_DIR
set -euo pipefail

bin=$1
source=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

printf 'package latin\n  port type P()\n  atom type A()\n    data string s\n    export port P p()\n    place S\n    initial to S do { s = "caf\xe9"; }\n    on p from S to S\n  end\n  compound type Top()\n    component A a()\n    connector Solo c(a.p)\n  end\n  connector type Solo(P p)\n    define p\n  end\nend\n' >"$out/latin.bip"
status=0
"$bin/bipc" ir "$out/latin.bip" --root 'Top()' --json >"$out/ir.json" 2>"$out/ir.err" || status=$?
[[ $status -eq 2 ]] || { echo "bipc ir exited $status, expected 2"; cat "$out/ir.err"; exit 1; }
[[ ! -s "$out/ir.json" ]] || { echo "bipc ir wrote JSON for a refused model"; exit 1; }
grep -q "latin.bip:7:31: error: string literal holds the byte '\\\\xE9', which is not UTF-8" \
  "$out/ir.err" || { echo "unexpected message:"; cat "$out/ir.err"; exit 1; }

model="$out/caf"$'\xe9'".bip"
cp "$source/models/channel.bip" "$model"
echo 'P>=0.5 [ F[0,100] Channel.id_channel > 0 ]' >"$out/p.mtl"
"$bin/smcbip" check "$model" "$out/p.mtl" --root 'System()' --json >"$out/check.json"
python3 - "$out/check.json" <<'PY'
import json, sys
report = json.load(open(sys.argv[1], encoding="utf-8"))
name = report["model"]["file"]
assert name.endswith("caf\ufffd.bip"), name
assert report["results"][0]["verdict"] is True, report["results"][0]
PY
echo "non_utf8_text: ok"
