#!/usr/bin/env bash
# Times `smcbip prove` on the D-Finder benchmarks scaled to N: the dining philosophers taking
# both forks together (deadlock-free, neighbours never eat together) and one at a time
# (deadlocking), the gas station with N pumps and 2 customers per pump (deadlock-free, one
# customer per pump) and N ATMs with 2 users each and one bank (deadlock-free, at most one ATM in
# the bank).
#
# Usage: [VARIANTS="together one_at_a_time gas_station atm"] [METHOD=both]
#        bench/fdir_philosophers.sh BIN_DIR N...
# Prints one line per model: N, variant, each query's verdict and method, exit status, seconds.
set -euo pipefail

[[ $# -ge 2 ]] || { echo "usage: fdir_philosophers.sh BIN_DIR N..." >&2; exit 2; }
bin_dir=$1
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The port and connector types every model uses.
write_types() {
  echo "  port type Sync()"
  echo "  connector type Two(Sync a, Sync b)"
  echo "    define a b"
  echo "  end"
  echo "  connector type Three(Sync a, Sync b, Sync c)"
  echo "    define a b c"
  echo "  end"
}

# write_atom NAME PORTS PLACES TRANSITION...: an atom type whose first place is initial; each
# transition is "port from to".
write_atom() {
  local name=$1 ports=$2 places=$3 t
  shift 3
  echo "  atom type $name()"
  echo "    export port Sync $ports"
  echo "    place $places"
  echo "    initial to ${places%%,*}"
  for t in "$@"; do
    read -r port from to <<< "$t"
    echo "    on $port from $from to $to"
  done
  echo "  end"
}

# write_philosophers VARIANT N (together | one_at_a_time).
write_philosophers() {
  local variant=$1 n=$2 i next
  write_atom Fork "take(), put()" "free, taken" "take free taken" "put taken free"
  if [[ $variant == together ]]; then
    write_atom Philosopher "take(), release()" "thinking, eating" "take thinking eating" \
      "release eating thinking"
  else
    write_atom Philosopher "take_left(), take_right(), release()" "thinking, has_left, eating" \
      "take_left thinking has_left" "take_right has_left eating" "release eating thinking"
  fi
  echo "  compound type Top()"
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
}

# write_gas_station N: as models/fdir/benchmarks/gas_station.bip, with N pumps.
write_gas_station() {
  local n=$1 j k c
  write_atom Customer "prepay(), activated(), start(), finish(), change()" \
    "idle, paid, authorised, pumping, waiting_change" "prepay idle paid" \
    "activated paid authorised" "start authorised pumping" "finish pumping waiting_change" \
    "change waiting_change idle"
  write_atom Pump "reserve(), activate(), start(), finish(), report()" \
    "off, reserved, ready, pumping, done" "reserve off reserved" "activate reserved ready" \
    "start ready pumping" "finish pumping done" "report done off"
  write_atom Operator "prepay(), activate(), report(), change()" "idle, activating, returning" \
    "prepay idle activating" "activate activating idle" "report idle returning" \
    "change returning idle"
  echo "  compound type Top()"
  echo "    component Operator operator()"
  for ((j = 0; j < n; j++)); do
    echo "    component Pump pump$j()"
    echo "    connector Two report$j(pump$j.report, operator.report)"
    for ((k = 0; k < 2; k++)); do
      c=c${j}_$k
      echo "    component Customer $c()"
      echo "    connector Three prepay$c($c.prepay, operator.prepay, pump$j.reserve)"
      echo "    connector Three activate$c(operator.activate, pump$j.activate, $c.activated)"
      echo "    connector Two start$c($c.start, pump$j.start)"
      echo "    connector Two finish$c($c.finish, pump$j.finish)"
      echo "    connector Two change$c(operator.change, $c.change)"
    done
  done
  echo "  end"
}

# write_atm N: as models/fdir/benchmarks/atm.bip, with N ATMs.
write_atm() {
  local n=$1 j k u
  write_atom User "insert(), pin(), take()" "outside, inserted, waiting" \
    "insert outside inserted" "pin inserted waiting" "take waiting outside"
  write_atom Atm "insert(), pin(), request(), reply(), dispense()" \
    "idle, card, asking, in_bank, paying" "insert idle card" "pin card asking" \
    "request asking in_bank" "reply in_bank paying" "dispense paying idle"
  write_atom Bank "request(), reply()" "free, busy" "request free busy" "reply busy free"
  echo "  compound type Top()"
  echo "    component Bank bank()"
  for ((j = 0; j < n; j++)); do
    echo "    component Atm atm$j()"
    echo "    connector Two request$j(atm$j.request, bank.request)"
    echo "    connector Two reply$j(bank.reply, atm$j.reply)"
    for ((k = 0; k < 2; k++)); do
      u=u${j}_$k
      echo "    component User $u()"
      echo "    connector Two insert$u($u.insert, atm$j.insert)"
      echo "    connector Two pin$u($u.pin, atm$j.pin)"
      echo "    connector Two take$u(atm$j.dispense, $u.take)"
    done
  done
  echo "  end"
}

# write_model VARIANT N: the BIP package on stdout.
write_model() {
  echo "package bench"
  write_types
  case $1 in
    together | one_at_a_time) write_philosophers "$1" "$2" ;;
    gas_station) write_gas_station "$2" ;;
    atm) write_atm "$2" ;;
  esac
  echo "end"
}

# write_queries VARIANT N: the property file on stdout.
write_queries() {
  echo "A[] !deadlock"
  case $1 in
    together) echo "A[] !(ROOT.p0.eating && ROOT.p1.eating)" ;;
    gas_station) echo "A[] !(ROOT.c0_0.pumping && ROOT.c0_1.pumping)" ;;
    atm) [[ $2 -ge 2 ]] && echo "A[] !(ROOT.atm0.in_bank && ROOT.atm1.in_bank)" ;;
  esac
  return 0
}

printf "%6s %-14s %-42s %4s %8s\n" N variant "verdicts (method)" exit seconds
for n in "$@"; do
  for variant in ${VARIANTS:-together one_at_a_time gas_station atm}; do
    write_model "$variant" "$n" > "$work/model.bip"
    write_queries "$variant" "$n" > "$work/queries.mtl"
    start=$(date +%s.%N)
    status=0
    out=$("$bin_dir/smcbip" prove "$work/model.bip" "$work/queries.mtl" --root 'Top()' \
      --method "${METHOD:-both}" --explore-depth "$((3 * n))" 2>&1) || status=$?
    end=$(date +%s.%N)
    verdicts=$(sed -n 's/^[AE][^ ]* .*  \([a-z]*\) (\([a-z]*\);.*/\1 (\2)/p' <<< "$out" |
      paste -sd, -)
    printf "%6d %-14s %-42s %4d %8.2f\n" "$n" "$variant" "${verdicts:-error}" "$status" \
      "$(echo "$end - $start" | bc)"
  done
done
