#!/usr/bin/env bash
# Runs one self-describing golden file (cvc5-style regression) and checks what its header promises.
#
# Usage: run_golden.sh BIN_DIR FILE
#
# The header is the block of '//' comment lines (and blank lines) at the top of FILE:
#   // COMMAND: bipc check %s --root 'Top()'   exactly one; %s = FILE, %d = FILE's directory;
#                                              a leading tool name is run from BIN_DIR
#   // EXIT: 2                                 required; the expected exit status
#   // EXPECT-ERROR: 14:9: undeclared place    stderr has a line starting '<FILE>:14:9: error:'
#                                              that contains the text (case-insensitive);
#                                              without 'L:C:', any stderr line containing
#                                              'error' and the text
#   // EXPECT-WARNING: 9:5: non-determinism    the same for '<FILE>:9:5: warning:' (a position
#                                              is required)
#   // EXPECT: some text                       stdout contains the text (exact substring)
# EXPECT-ERROR, EXPECT-WARNING and EXPECT may repeat; all must hold. The command runs under bash -c (so
# single quotes group words) with a 60 s timeout.
#
# Exit status: 0 when every expectation holds, 1 otherwise (including a malformed header).

set -u

readonly TIMEOUT_SECONDS=60
readonly MAX_SHOWN_LINES=40

usage() {
  echo "usage: run_golden.sh BIN_DIR FILE" >&2
  exit 1
}

[[ $# -eq 2 ]] || usage
bin_dir=$1
file=$2

if [[ ! -f $file ]]; then
  echo "run_golden: no such file: $file" >&2
  exit 1
fi
if [[ ! -d $bin_dir ]]; then
  echo "run_golden: no such directory: $bin_dir" >&2
  exit 1
fi

file_dir=$(dirname -- "$file")
file_base=$(basename -- "$file")

# ---------------------------------------------------------------- read the header
command_line=""
command_count=0
expected_exit=""
expect_errors=()
expect_warnings=()
expect_outputs=()

while IFS= read -r line || [[ -n $line ]]; do
  line=${line%$'\r'}
  if [[ $line =~ ^[[:space:]]*$ ]]; then
    continue
  fi
  [[ $line == //* ]] || break
  if [[ $line =~ ^//[[:space:]]*COMMAND:[[:space:]]*(.*)$ ]]; then
    command_line=${BASH_REMATCH[1]}
    command_count=$((command_count + 1))
  elif [[ $line =~ ^//[[:space:]]*EXIT:[[:space:]]*([0-9]+)[[:space:]]*$ ]]; then
    expected_exit=${BASH_REMATCH[1]}
  elif [[ $line =~ ^//[[:space:]]*EXIT: ]]; then
    echo "FAIL $file: malformed EXIT line: $line"
    exit 1
  elif [[ $line =~ ^//[[:space:]]*EXPECT-ERROR:[[:space:]]*(.*[^[:space:]])[[:space:]]*$ ]]; then
    expect_errors+=("${BASH_REMATCH[1]}")
  elif [[ $line =~ ^//[[:space:]]*EXPECT-ERROR: ]]; then
    echo "FAIL $file: empty EXPECT-ERROR line"
    exit 1
  elif [[ $line =~ ^//[[:space:]]*EXPECT-WARNING:[[:space:]]*([0-9]+):([0-9]+):[[:space:]]*(.*[^[:space:]])[[:space:]]*$ ]]; then
    expect_warnings+=("${BASH_REMATCH[1]}:${BASH_REMATCH[2]}:${BASH_REMATCH[3]}")
  elif [[ $line =~ ^//[[:space:]]*EXPECT-WARNING: ]]; then
    echo "FAIL $file: EXPECT-WARNING needs 'LINE:COL: text': $line"
    exit 1
  elif [[ $line =~ ^//[[:space:]]*EXPECT:[[:space:]]?(.*)$ ]]; then
    expect_outputs+=("${BASH_REMATCH[1]}")
  fi
done < "$file"

if [[ $command_count -ne 1 ]]; then
  echo "FAIL $file: header needs exactly one '// COMMAND:' line (found $command_count)"
  exit 1
fi
if [[ -z $expected_exit ]]; then
  echo "FAIL $file: header lacks an '// EXIT:' line"
  exit 1
fi

# ---------------------------------------------------------------- build the command
# Paths are substituted shell-quoted, so that files in directories with spaces still work.
quoted_file=$(printf '%q' "$file")
quoted_dir=$(printf '%q' "$file_dir")
cmd=${command_line//%s/$quoted_file}
cmd=${cmd//%d/$quoted_dir}

if [[ $cmd =~ ^([A-Za-z0-9_.-]+)(.*)$ ]]; then
  tool=${BASH_REMATCH[1]}
  rest=${BASH_REMATCH[2]}
  if [[ -x $bin_dir/$tool ]]; then
    cmd="$(printf '%q' "$bin_dir/$tool")$rest"
  elif [[ $tool == bipc || $tool == smcbip ]]; then
    echo "FAIL $file: tool '$tool' not found (or not executable) in $bin_dir"
    exit 1
  fi
fi

work_dir=$(mktemp -d "${TMPDIR:-/tmp}/run_golden.XXXXXX") || exit 1
trap 'rm -rf -- "$work_dir"' EXIT
stdout_file=$work_dir/stdout
stderr_file=$work_dir/stderr

timeout "$TIMEOUT_SECONDS" bash -c "$cmd" > "$stdout_file" 2> "$stderr_file" < /dev/null
actual_exit=$?

# ---------------------------------------------------------------- check
failures=()

if [[ $actual_exit -eq 124 ]]; then
  failures+=("timed out after ${TIMEOUT_SECONDS}s")
elif [[ $actual_exit -ne $expected_exit ]]; then
  failures+=("exit status: expected $expected_exit, got $actual_exit")
fi

lowercase() { printf '%s' "${1,,}"; }

# Succeeds when stderr has '<path>:L:C: SEVERITY:' (path naming FILE) followed by the phrase.
has_positioned() {
  local severity=$1 wanted_line=$2 wanted_col=$3 phrase
  phrase=$(lowercase "$4")
  local marker=":$wanted_line:$wanted_col: $severity:" line prefix rest
  while IFS= read -r line || [[ -n $line ]]; do
    [[ $line == *"$marker"* ]] || continue
    prefix=${line%%"$marker"*}
    rest=${line#*"$marker"}
    if [[ $prefix == "$file" || ${prefix##*/} == "$file_base" ]]; then
      [[ $(lowercase "$rest") == *"$phrase"* ]] && return 0
    fi
  done < "$stderr_file"
  return 1
}

# Succeeds when some stderr line mentions 'error' and contains the phrase.
has_unpositioned_error() {
  local phrase line lower
  phrase=$(lowercase "$1")
  while IFS= read -r line || [[ -n $line ]]; do
    lower=$(lowercase "$line")
    [[ $lower == *error* && $lower == *"$phrase"* ]] && return 0
  done < "$stderr_file"
  return 1
}

for expectation in "${expect_errors[@]+"${expect_errors[@]}"}"; do
  if [[ $expectation =~ ^([0-9]+):([0-9]+):[[:space:]]*(.*)$ ]]; then
    if ! has_positioned error "${BASH_REMATCH[1]}" "${BASH_REMATCH[2]}" "${BASH_REMATCH[3]}"; then
      failures+=("stderr lacks: $file_base:${BASH_REMATCH[1]}:${BASH_REMATCH[2]}: error: ...${BASH_REMATCH[3]}...")
    fi
  elif ! has_unpositioned_error "$expectation"; then
    failures+=("stderr lacks an error line containing: $expectation")
  fi
done

for expectation in "${expect_warnings[@]+"${expect_warnings[@]}"}"; do
  [[ $expectation =~ ^([0-9]+):([0-9]+):(.*)$ ]]
  if ! has_positioned warning "${BASH_REMATCH[1]}" "${BASH_REMATCH[2]}" "${BASH_REMATCH[3]}"; then
    failures+=("stderr lacks: $file_base:${BASH_REMATCH[1]}:${BASH_REMATCH[2]}: warning: ...${BASH_REMATCH[3]}...")
  fi
done

for expectation in "${expect_outputs[@]+"${expect_outputs[@]}"}"; do
  if ! grep -qF -- "$expectation" "$stdout_file"; then
    failures+=("stdout lacks: $expectation")
  fi
done

if [[ ${#failures[@]} -eq 0 ]]; then
  echo "PASS $file"
  exit 0
fi

show_stream() {
  local name=$1 path=$2 total
  total=$(wc -l < "$path")
  echo "+++ actual $name ($total lines)"
  head -n "$MAX_SHOWN_LINES" -- "$path" | sed 's/^/+ /'
  if [[ $total -gt $MAX_SHOWN_LINES ]]; then
    echo "+ ... ($((total - MAX_SHOWN_LINES)) more lines)"
  fi
}

echo "FAIL $file"
echo "    command: $cmd"
echo "--- expected"
echo "- exit $expected_exit"
for expectation in "${expect_errors[@]+"${expect_errors[@]}"}"; do
  echo "- stderr: $expectation"
done
for expectation in "${expect_warnings[@]+"${expect_warnings[@]}"}"; do
  echo "- stderr warning: $expectation"
done
for expectation in "${expect_outputs[@]+"${expect_outputs[@]}"}"; do
  echo "- stdout: $expectation"
done
echo "+++ actual"
echo "+ exit $actual_exit"
show_stream stderr "$stderr_file"
show_stream stdout "$stdout_file"
echo "*** problems"
for failure in "${failures[@]}"; do
  echo "! $failure"
done
exit 1
