#!/usr/bin/env bash
# smcbip check --compile: the model's plugin built once into the cache ($SMCBIP_CACHE_DIR, a
# scratch folder here), then used from it, with the answers of the interpreter (the generated
# code makes the same runs per seed as the interpreter, tests/codegen). Also: auto does not
# build for a check of a fraction of a second; an entry that cannot be loaded, a missing
# compiler and a failing build fall back to the interpreter with a warning and the same exit
# code; nothing half-built stays in the cache. One plugin is built (two processes race for it).
#
# Usage: compile_cache.sh BIN_DIR SOURCE_DIR
set -uo pipefail

bin=$1
source=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
failures=0
export SMCBIP_CACHE_DIR=$out/cache
model=$source/models/knuth_yao.bip
props=$source/models/knuth_yao.mtl
check=("$bin/smcbip" check "$model" "$props" --threads 1 --json)
hash=$("$bin/bipc" hash "$model")

fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# The answers of a --json result, without the seconds they took.
answers() { grep -v '"seconds"' "$1"; }

# judged NAME CODE: the check NAME exited with CODE, as the interpreted check did, and gave its
# answers.
judged() {
  [[ $2 == "$expected_code" ]] || fail "$1: exit $2, not $expected_code: $(cat "$out/$1.err")"
  answers "$out/$1.json" | cmp -s - <(answers "$out/never.json") ||
    fail "$1: answers differ from --compile never: $(diff <(answers "$out/never.json") \
      <(answers "$out/$1.json") | head -10)"
}

# run NAME [ENV...] -- ARGS...: the check with ARGS into NAME.json and NAME.err, judged.
run() {
  local name=$1
  shift
  local -a env=()
  while [[ $1 != -- ]]; do env+=("$1"); shift; done
  shift
  local code=0
  env "${env[@]+"${env[@]}"}" "${check[@]}" "$@" >"$out/$name.json" 2>"$out/$name.err" || code=$?
  judged "$name" "$code"
}

# has NAME PHRASE / lacks NAME PHRASE: NAME's stderr holds (or does not hold) PHRASE.
has() { grep -qF -- "$2" "$out/$1.err" || fail "$1: stderr lacks '$2': $(cat "$out/$1.err")"; }
lacks() { ! grep -qF -- "$2" "$out/$1.err" || fail "$1: stderr has '$2': $(cat "$out/$1.err")"; }

# entries: the cache's entries of this model (each a folder named after its hash).
entries() { find "$SMCBIP_CACHE_DIR" -mindepth 1 -maxdepth 1 -name "$hash-*" 2>/dev/null | wc -l; }
no_scratch() {
  [[ -z $(find "$SMCBIP_CACHE_DIR" -maxdepth 1 -name 'tmp-*' 2>/dev/null) ]] ||
    fail "$1: a temporary build folder stayed in the cache"
}

expected_code=0
"${check[@]}" --compile never >"$out/never.json" 2>"$out/never.err" || expected_code=$?
grep -q '"estimate"' "$out/never.json" || fail "the interpreted check gave no answers"

# --- a mode that is none of the three is a usage error
code=0
"${check[@]}" --compile sometimes >/dev/null 2>"$out/bad_mode.err" || code=$?
[[ $code == 2 ]] || fail "--compile sometimes exited with $code, not 2"
has bad_mode "--compile"

# --- auto: a check of a fraction of a second is not worth a build, and says nothing
run auto_small -- --compile auto
[[ -s $out/auto_small.err ]] && fail "auto on a small check printed: $(cat "$out/auto_small.err")"
[[ $(entries) == 0 ]] || fail "auto built the plugin of a check of a fraction of a second"

# --- a missing compiler: auto stays silent, always says why; both run interpreted
mkdir -p "$out/path"
for tool in cmake make ninja; do
  command -v "$tool" >/dev/null && ln -s "$(command -v "$tool")" "$out/path/$tool"
done
run no_compiler_auto PATH="$out/path" CXX= -- --compile auto
[[ -s $out/no_compiler_auto.err ]] && fail "auto without a compiler printed something"
run no_compiler_always PATH="$out/path" CXX= -- --compile always
has no_compiler_always "cannot compile the model (no C++ compiler"
has no_compiler_always "running it interpreted"

# --- a build that fails (a compiler that refuses everything) leaves nothing behind; the
# cache's folder comes from XDG_CACHE_HOME without SMCBIP_CACHE_DIR
printf '#!/bin/sh\necho "c++: error: refusing to compile" >&2\nexit 1\n' >"$out/path/c++"
chmod +x "$out/path/c++"
run broken_compiler PATH="$out/path" CXX= SMCBIP_CACHE_DIR= XDG_CACHE_HOME="$out/xdg" -- \
  --compile always
has broken_compiler "compiling the model (--compile always); cached in $out/xdg/smcbip"
has broken_compiler "smcbip: warning: could not compile the model (configuring failed"
[[ -z $(find "$out/xdg/smcbip" -mindepth 1 -maxdepth 1 ! -name lock) ]] ||
  fail "a failed build left $(ls "$out/xdg/smcbip") in the cache"

# --- always builds (two processes at once: the lock lets one build, the other then uses it)
"${check[@]}" --compile always >"$out/always_1.json" 2>"$out/always_1.err" &
first=$!
code=0
"${check[@]}" --compile always >"$out/always_2.json" 2>"$out/always_2.err" || code=$?
judged always_2 "$code"
code=0
wait "$first" || code=$?
judged always_1 "$code"
has always_1 "compiling the model (--compile always); cached in $SMCBIP_CACHE_DIR"
[[ $(entries) == 1 ]] || fail "always left $(entries) entries for the model, not 1"
no_scratch always

# --- a cached plugin is used, by auto too, by check and explore; --compiled wins
run hit -- --compile auto
has hit "smcbip: using the compiled model from the cache (hash ${hash:0:12}"
lacks hit "compiling"
"$bin/smcbip" explore "$model" "$props" --threads 1 --json --compile never \
  >"$out/explore_never.json" 2>/dev/null
"$bin/smcbip" explore "$model" "$props" --threads 1 --json >"$out/explore_hit.json" \
  2>"$out/explore_hit.err"
has explore_hit "using the compiled model from the cache"
answers "$out/explore_hit.json" | cmp -s - <(answers "$out/explore_never.json") ||
  fail "explore: the cached plugin's answers differ from the interpreter's"
entry=$(find "$SMCBIP_CACHE_DIR" -mindepth 1 -maxdepth 1 -name "$hash-*")
run given -- --compiled "$entry"
lacks given "from the cache"
run never_again -- --compile never
lacks never_again "from the cache"

# --- an entry of another smcbip build is not used
cp -r "$entry" "$SMCBIP_CACHE_DIR/$hash-0.0.0-abi0-other"
# --- an entry that cannot be loaded: a warning, removed, and the interpreter answers
head -c 4096 /dev/urandom >"$entry/model_plugin.so"
run corrupted -- --compile auto
has corrupted "smcbip: warning: the cached plugin cannot be used"
has corrupted "removed from the cache"
[[ -e $entry ]] && fail "the entry that could not be loaded is still in the cache"
run stale -- --compile auto
[[ -s $out/stale.err ]] && fail "an entry of another smcbip build was used: $(cat "$out/stale.err")"

if [[ $failures -gt 0 ]]; then
  echo "$failures failures" >&2
  exit 1
fi
echo "compile cache: built once, used from the cache, fell back on every failure"
