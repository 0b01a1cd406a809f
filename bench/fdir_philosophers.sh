#!/usr/bin/env bash
# Times `smcbip prove` on the dining philosophers taking both forks together (deadlock-free) and
# one at a time (deadlocking), for N philosophers, N given on the command line.
#
# Usage: [VARIANTS="together"] bench/fdir_philosophers.sh BIN_DIR N...
# Prints one line per model: N, variant, verdict, exit status and seconds.
set -euo pipefail

[[ $# -ge 2 ]] || { echo "usage: fdir_philosophers.sh BIN_DIR N..." >&2; exit 2; }
bin_dir=$1
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# write_model VARIANT N: the BIP package on stdout (together | one_at_a_time).
write_model() {
  local variant=$1 n=$2 i next
  echo "package philosophers"
  echo "  port type Sync()"
  echo "  connector type Two(Sync a, Sync b)"
  echo "    define a b"
  echo "  end"
  echo "  connector type Three(Sync a, Sync b, Sync c)"
  echo "    define a b c"
  echo "  end"
  echo "  atom type Fork()"
  echo "    export port Sync take(), put()"
  echo "    place free, taken"
  echo "    initial to free"
  echo "    on take from free to taken"
  echo "    on put from taken to free"
  echo "  end"
  echo "  atom type Philosopher()"
  if [[ $variant == together ]]; then
    echo "    export port Sync take(), release()"
    echo "    place thinking, eating"
    echo "    initial to thinking"
    echo "    on take from thinking to eating"
  else
    echo "    export port Sync take_left(), take_right(), release()"
    echo "    place thinking, has_left, eating"
    echo "    initial to thinking"
    echo "    on take_left from thinking to has_left"
    echo "    on take_right from has_left to eating"
  fi
  echo "    on release from eating to thinking"
  echo "  end"
  echo "  compound type Table()"
  for ((i = 0; i < n; i++)); do
    echo "    component Philosopher p$i()"
    echo "    component Fork f$i()"
  done
  for ((i = 0; i < n; i++)); do
    next=$(((i + 1) % n))
    if [[ $variant == together ]]; then
      echo "    connector Three take$i(p$i.take, f$i.take, f$next.take)"
    else
      echo "    connector Two left$i(p$i.take_left, f$i.take)"
      echo "    connector Two right$i(p$i.take_right, f$next.take)"
    fi
    echo "    connector Three release$i(p$i.release, f$i.put, f$next.put)"
  done
  echo "  end"
  echo "end"
}

echo "A[] !deadlock" > "$work/deadlock.mtl"
printf "%6s %-14s %-8s %4s %8s\n" N variant verdict exit seconds
for n in "$@"; do
  for variant in ${VARIANTS:-together one_at_a_time}; do
    write_model "$variant" "$n" > "$work/model.bip"
    start=$(date +%s.%N)
    status=0
    out=$("$bin_dir/smcbip" prove "$work/model.bip" "$work/deadlock.mtl" --explore-depth "$n" \
      2>&1) || status=$?
    end=$(date +%s.%N)
    verdict=$(sed -n '1s/^A\[\] !deadlock  \([a-z]*\).*/\1/p' <<< "$out")
    printf "%6d %-14s %-8s %4d %8.2f\n" "$n" "$variant" "${verdict:-error}" "$status" \
      "$(echo "$end - $start" | bc)"
  done
done
