#!/usr/bin/env bash
# smcbip check beside the statistical model checkers Ymer and PRISM on their own kind of
# benchmarks: the tandem queue (c = 7, `P=? [ F<=26 sc=c & sm=c ]`) at the sample sizes of
# PESTIM with alpha 0.01 and delta 0.01 (26,492 runs) and 0.005 (105,966), Knuth and Yao's die
# (`P=? [ F s=7 & d=1 ]`, delta 0.002: 662,290 runs) and Wald's SPRT of `P<0.12` on the tandem
# queue (alpha = beta = 0.01, delta 0.01). Each tool runs one thread on the same sample size
# (PRISM only 100,000 runs of the die and none of the larger tandem case: it is slow there), the
# tools interleaved, REPEAT times (default 5); it prints the median wall-clock and CPU (user and
# system) seconds of each (the whole process: parsing included, and PRISM's JVM start), runs per
# second, the answer, and each peer's CPU time per run over smcbip's (whole tests for the SPRT;
# above 1: smcbip is faster). CPU time, because a machine shared with other work stretches wall
# time by its load; PRISM's JVM counts the CPU of its compiler and collector threads too.
# smcbip runs interpreted (`--compile never`): a plugin cached by an earlier check would
# otherwise make the figures depend on what ran before. Beside it, unless COMPILED=0, the row
# `compiled` is smcbip on the model's generated code, as a check finds it in its cache once an
# earlier check built it: the plugins are built into a fresh cache folder before the timed
# runs (that build is not timed; `--compile auto` makes it when the runs are expected to take
# longer), and the last column gives each peer's time per run over this row's.
#
# The peers are found through the environment, e.g. YMER=/path/to/ymer PRISM=/path/to/prism
# (PRISM's bin/prism script); without them it prints smcbip's own figures and names what is
# missing. The models the peers read are bench/peers/*.sm (transcriptions of models/tandem.bip
# and models/knuth_yao.bip into PRISM's language) with the properties bench/peers/*.csl.
#
# Usage: [YMER=...] [PRISM=...] [REPEAT=5] [COMPILED=0] bench/peers.sh [BUILD_DIR]
#        (default: build)
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
build_dir=${1:-build}
smcbip="$build_dir/bin/smcbip"
repeat=${REPEAT:-5}
peers=bench/peers
if [[ ! -x "$smcbip" ]]; then
  echo "peers: $smcbip not found; build first (make build)" >&2
  exit 2
fi
for peer in YMER PRISM; do
  path=${!peer:-}
  if [[ -z "$path" ]]; then
    echo "peers: $peer not set: its columns are left out (set $peer=/path/to/${peer,,})"
  elif [[ ! -x "$path" ]]; then
    echo "peers: $peer=$path is not an executable" >&2
    exit 2
  fi
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
grep -v '^param' models/knuth_yao.mtl >"$work/die.mtl"
sed -i 's/^P=?/const k = 1\nP=?/' "$work/die.mtl"

# The cases: name, then per tool the command line (empty: not run), and each tool's runs.
declare -A command runs
cache="$work/cache"
add_case() {  # name smcbip-args ymer-args prism-args
  command[$1/smcbip]="$smcbip check $2 --threads 1 --json --compile never"
  if [[ ${COMPILED:-1} != 0 ]]; then
    command[$1/compiled]="env SMCBIP_CACHE_DIR=$cache $smcbip check $2 --threads 1 --json"
  fi
  command[$1/ymer]=${YMER:+${3:+$YMER $3}}
  command[$1/prism]=${PRISM:+${4:+$PRISM $4}}
}
cases=(tandem_26492 tandem_105966 die_662290 tandem_sprt)
add_case tandem_26492 "models/tandem.bip models/tandem.mtl --alpha 0.01 --delta 0.01" \
  "-S 1 -N 26492 $peers/tandem.sm $peers/tandem.csl" \
  "$peers/tandem.sm $peers/tandem.csl -sim -simmethod apmc -simsamples 26492 -simconf 0.01"
add_case tandem_105966 "models/tandem.bip models/tandem.mtl --alpha 0.01 --delta 0.005" \
  "-S 1 -N 105966 $peers/tandem.sm $peers/tandem.csl" ""
add_case die_662290 "models/knuth_yao.bip $work/die.mtl --alpha 0.01 --delta 0.002" \
  "-S 1 -N 662290 $peers/die.sm $peers/die.csl" \
  "$peers/die.sm $peers/die.csl -sim -simmethod apmc -simsamples 100000 -simconf 0.01"
add_case tandem_sprt "models/tandem.bip $peers/tandem_sprt.mtl --alpha 0.01 --beta 0.01 --delta 0.01" \
  "-S 1 -A 0.01 -B 0.01 -D 0.01 $peers/tandem.sm $peers/tandem_sprt.csl" \
  "$peers/tandem.sm $peers/tandem_sprt.csl -sim -simmethod sprt -simconf 0.01 -simwidth 0.01"

# The runs and the answer of one tool's output.
read_answer() {  # tool output-file
  case $1 in
    smcbip | compiled)
      python3 -c 'import json, sys
r = json.load(open(sys.argv[1]))["results"][0]
a = r.get("verdict")
a = round(r["estimate"], 5) if a is None else a
print(r["samples"] + r["undecided"], str(a).lower())' "$2" ;;
    ymer)
      local n a
      n=$(grep -o '[0-9]* observations' "$2" | tail -1 | cut -d' ' -f1 || true)
      a=$(grep -oE '^Pr\[.*\] = [0-9.e-]+' "$2" | sed 's/.* = //' || true)
      if [[ -z $a ]]; then a=$(grep -q 'Property is true' "$2" && echo true || echo false); fi
      echo "${n:-?} $a" ;;
    prism)
      local n a
      n=$(grep -oE 'number of samples=[0-9]+' "$2" | cut -d= -f2 || true)
      a=$(grep -oE '^Result: [^ ]+' "$2" | cut -d' ' -f2 || true)
      echo "${n:-?} ${a:-?}" ;;
  esac
}

# The compiled model of each model file, built once into the cache before anything is timed.
if [[ ${COMPILED:-1} != 0 ]]; then
  for model in models/tandem.bip models/knuth_yao.bip; do
    property=$([[ $model == *tandem* ]] && echo models/tandem.mtl || echo "$work/die.mtl")
    if ! SMCBIP_CACHE_DIR=$cache "$smcbip" check "$model" "$property" --alpha 0.1 --delta 0.1 \
      --threads 1 --compile always >/dev/null 2>"$work/err" || grep -q warning "$work/err"; then
      echo "peers: the compiled model of $model could not be built; its rows are left out:"
      cat "$work/err"
      for c in "${cases[@]}"; do unset "command[$c/compiled]"; done
      break
    fi
  done
fi

echo "peers: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg); one thread each, median of $repeat"
declare -A times cpus answer
TIMEFORMAT='%R %U %S'
tools=(smcbip compiled ymer prism)
for ((k = 0; k < repeat; k++)); do
  # The tools' order turns by one at each repetition: the run after PRISM's (a JVM that keeps
  # both cores busy) was slower whichever tool it was, and would otherwise always be smcbip's.
  order=("${tools[@]:k % 4}" "${tools[@]:0:k % 4}")
  for c in "${cases[@]}"; do
    for tool in "${order[@]}"; do
      cmd=${command[$c/$tool]:-}
      [[ -z $cmd ]] && continue
      # Ymer and PRISM write their answer to stdout, smcbip its JSON (its exit code is the
      # verdict's); the command lines hold no spaces but between words.
      status=0
      # shellcheck disable=SC2086
      { time $cmd >"$work/out" 2>"$work/err" || status=$?; } 2>"$work/time"
      if [[ $tool == compiled ]] && ! grep -q "using the compiled model" "$work/err"; then
        echo "peers: the compiled run of $c did not use the cached plugin:" >&2
        cat "$work/err" >&2
        exit 1
      fi
      if ((status != 0)) && [[ $tool != smcbip && $tool != compiled ]]; then
        echo "peers: $tool failed on $c: $cmd" >&2
        cat "$work/out" "$work/err" >&2
        exit 1
      fi
      read -r wall cpu <"$work/time"
      times[$c/$tool]+="$wall "
      cpus[$c/$tool]+="$cpu "
      # A command substitution, not a process substitution: the shell waits for the reader (a
      # Python process for smcbip's JSON) here, where a process substitution would leave it to
      # be reaped during the next timed command, whose CPU time would then include it.
      found=$(read_answer "$tool" "$work/out")
      read -r "runs[$c/$tool]" "answer[$c/$tool]" <<<"$found"
    done
  done
done

median() { tr ' ' '\n' | grep . | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
# CPU: user plus system seconds, summed per run before the median.
cpu_median() { tr ' ' '\n' <<<"${cpus[$1]}" | paste - - | awk '{ print $1 + $2 }' | tr '\n' ' ' | median; }
printf '%-14s %-8s %8s %8s %8s %10s %-9s %-12s %s\n' case tool runs wall/s cpu/s runs/s answer \
  "peer/smcbip" "peer/compiled"
# A peer's CPU time over a base tool's: per run in the fixed-size cases (PRISM makes fewer runs
# of the die), whole tests in the sequential one (run counts differ by method); empty for the
# base itself or when the base did not run.
ratio() {  # case tool base
  [[ $2 == "$3" || -z ${cpus[$1/$3]:-} ]] && return
  awk -v u="$(cpu_median "$1/$2")" -v n="${runs[$1/$2]}" -v b="$(cpu_median "$1/$3")" \
    -v nb="${runs[$1/$3]}" -v sprt="${1/*sprt*/1}" '
    BEGIN { printf "%.2f", (sprt == 1 || n !~ /^[0-9]+$/) ? u / b : (u / n) / (b / nb) }'
}
for c in "${cases[@]}"; do
  for tool in smcbip compiled ymer prism; do
    [[ -z ${times[$c/$tool]:-} ]] && continue
    m=$(median <<<"${times[$c/$tool]}")
    cpu=$(cpu_median "$c/$tool")
    over_compiled=$([[ $tool == smcbip ]] || ratio "$c" "$tool" compiled)
    awk -v c="$c" -v t="$tool" -v n="${runs[$c/$tool]}" -v m="$m" -v u="$cpu" \
      -v a="${answer[$c/$tool]}" -v r="$(ratio "$c" "$tool" smcbip)" -v rc="$over_compiled" '
      BEGIN {
        if (a ~ /^[0-9.]+$/) a = sprintf("%.5f", a)
        printf "%-14s %-8s %8s %8.3f %8.3f %10s %-9s %-12s %s\n", c, t, n, m, u,
          n ~ /^[0-9]+$/ ? sprintf("%.0f", n / m) : "-", a, r, rc
      }'
  done
done
