#!/usr/bin/env bash
# Counterexamples of `smcbip prove --trace-out` replay with `smcbip simulate --replay`: the
# philosophers taking their forks one at a time end in the deadlock the prover found, a witness
# with data reaches the recorded values, and tampered traces are refused at their line.
#
# Usage: replay_test.sh BIN_DIR SOURCE_DIR
set -u
bin=$1/smcbip
src=$2
bench=$src/models/fdir/benchmarks
work=$(mktemp -d "${TMPDIR:-/tmp}/replay_test.XXXXXX") || exit 1
trap 'rm -rf -- "$work"' EXIT

fail() {
  echo "FAIL: $*"
  exit 1
}

# The deadlock: prove fails (exit 1) and writes the trace, the initial state and 3 steps.
"$bin" prove "$bench/philosophers_one_at_a_time.bip" "$bench/deadlock.mtl" \
  --trace-out "$work/deadlock.jsonl" > "$work/prove.out"
[[ $? -eq 1 ]] || fail "prove should find the deadlock"
[[ $(grep -c '"step"' "$work/deadlock.jsonl") -eq 4 ]] || fail "expected 4 states in the trace"
[[ $(tail -n 1 "$work/deadlock.jsonl") == '{"end":"deadlock"}' ]] || fail "the trace should end in a deadlock"

# Its replay fires the same interactions and ends in that deadlock (run code 0).
"$bin" simulate "$bench/philosophers_one_at_a_time.bip" --replay "$work/deadlock.jsonl" \
  > "$work/replay.out" 2> "$work/replay.err" || fail "the replay failed: $(cat "$work/replay.err")"
grep -q 'state #3 and global time 0: deadlock!' "$work/replay.out" || fail "the replay should deadlock at step 3"
for k in 0 1 2; do
  grep -q "choose \[[0-9]\] ROOT.left$k: p$k.take_left() f$k.take()" "$work/replay.out" ||
    fail "the replay should take left fork $k"
done

# Tampered: at step 2 the trace fires philosopher 1's right fork, not enabled before its left one.
sed 's/"interaction":"ROOT.left1: p1.take_left() f1.take()"/"interaction":"ROOT.right1: p1.take_right() f2.take()"/' \
  "$work/deadlock.jsonl" > "$work/tampered.jsonl"
"$bin" simulate "$bench/philosophers_one_at_a_time.bip" --replay "$work/tampered.jsonl" \
  > /dev/null 2> "$work/tampered.err"
[[ $? -eq 65 ]] || fail "a tampered trace should be refused with exit 65"
grep -qF "tampered.jsonl:4: error: step 2: interaction ROOT.right1: p1.take_right() f2.take() is not enabled; enabled: ROOT.left1: p1.take_left() f1.take()," \
  "$work/tampered.err" || fail "unexpected error: $(cat "$work/tampered.err")"

# Tampered state: the trace claims philosopher 2 still thinks after the last step.
sed '5s/"ROOT.p2":\["has_left"\]/"ROOT.p2":["thinking"]/' "$work/deadlock.jsonl" > "$work/state.jsonl"
"$bin" simulate "$bench/philosophers_one_at_a_time.bip" --replay "$work/state.jsonl" \
  > /dev/null 2> "$work/state.err"
[[ $? -eq 65 ]] || fail "a trace with a wrong state should be refused"
grep -qF "state.jsonl:5: error: step 3: the state differs from the trace's: atom ROOT.p2 marks has_left" \
  "$work/state.err" || fail "unexpected error: $(cat "$work/state.err")"

# A witness with data (E<> holds): the replay reaches the recorded values.
printf 'E<> c.y == 2\n' > "$work/witness.mtl"
"$bin" prove "$bench/producer_consumer.bip" --root 'Top(3)' "$work/witness.mtl" \
  --trace-out "$work/witness.jsonl" > /dev/null || fail "E<> c.y == 2 should hold"
grep -q '"ROOT.c.y":2' "$work/witness.jsonl" || fail "the witness should reach y = 2"
"$bin" simulate "$bench/producer_consumer.bip" --root 'Top(3)' --replay "$work/witness.jsonl" \
  -s 2> "$work/witness.err" || fail "the witness does not replay: $(cat "$work/witness.err")"
sed 's/"ROOT.c.y":2/"ROOT.c.y":3/' "$work/witness.jsonl" > "$work/data.jsonl"
"$bin" simulate "$bench/producer_consumer.bip" --root 'Top(3)' --replay "$work/data.jsonl" \
  -s 2> "$work/data.err"
[[ $? -eq 65 ]] && grep -qF 'ROOT.c.y is 2, the trace has 3' "$work/data.err" ||
  fail "a wrong datum should be refused: $(cat "$work/data.err")"

# A simulated run of a timed model replays at its recorded dates: the same states and times
# again (the header's seed and the end line, `limit` for the run, `stopped` for the replay, aside).
"$bin" simulate "$src/tests/fdir/models/ticking.bip" --seed 5 --limit 6 --trace jsonl \
  > "$work/timed.jsonl" || fail "the timed run failed"
"$bin" simulate "$src/tests/fdir/models/ticking.bip" --replay "$work/timed.jsonl" --trace jsonl \
  > "$work/timed_replay.jsonl" || fail "the timed run does not replay"
[[ $(grep -c '"step"' "$work/timed.jsonl") -eq 7 ]] || fail "expected 7 states in the timed run"
diff <(sed '1d;$d' "$work/timed.jsonl") <(sed '1d;$d' "$work/timed_replay.jsonl") ||
  fail "the timed replay differs from the run"

# Nothing is written when no query has a trace, nor into a folder that does not exist.
"$bin" prove "$bench/philosophers_together.bip" "$bench/deadlock.mtl" \
  --trace-out "$work/none.jsonl" > /dev/null 2>&1
[[ $? -eq 0 && ! -e $work/none.jsonl ]] || fail "no trace should be written when every query holds"
"$bin" prove "$bench/philosophers_one_at_a_time.bip" "$bench/deadlock.mtl" \
  --trace-out "$work/missing/ce.jsonl" > /dev/null 2>&1
[[ $? -eq 2 && ! -e $work/missing ]] || fail "an unwritable --trace-out should fail with exit 2"

echo "PASS replay_test"
