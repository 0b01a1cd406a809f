# Timing helpers of the smcbip check benchmarks (sourced): they use $smcbip, $delta and $repeat.

# Prints "runs seconds" of the fastest of $repeat `smcbip check` runs of the first query of
# property file $3 on model $1 (root $2), launched by the command in the rest of the arguments
# before smcbip (none, or e.g. mpirun -np 4), with $threads threads.
best_check() {
  local model=$1 root=$2 properties=$3
  shift 3
  for ((k = 0; k < repeat; k++)); do
    "$@" "$smcbip" check "$model" "$properties" --root "$root" --delta "$delta" \
      --threads "$threads" --json --compile never
  done | python3 -c 'import json, sys
text = sys.stdin.read()
decoder, at, best = json.JSONDecoder(), 0, None
while at < len(text):
    r, at = decoder.raw_decode(text, at)
    r = r["results"][0]
    if best is None or r["seconds"] < best[1]:
        best = (r["samples"] + r["undecided"], r["seconds"])
    while at < len(text) and text[at].isspace():
        at += 1
print(*best)'
}
