// The exit codes of every smcbip tool, declared once (DESIGN.md, "Command-line tools").
#pragma once

namespace smcbip::exit_codes {

// bipc and smcbip check|explore|monitor, after grep: the answer, then what went wrong.
inline constexpr int kSuccess = 0;        // success, or every property holds
inline constexpr int kPropertyFails = 1;  // a property does not hold
inline constexpr int kInputError = 2;     // bad input or usage
inline constexpr int kInternalError = 3;

// smcbip simulate and generated executables, whose result is a run: the reference engine's run
// codes 0 to 7 (engines::RunCode), then sysexits codes for the tool's own errors, so that the
// two never collide.
inline constexpr int kRunUsageError = 64;     // EX_USAGE
inline constexpr int kRunInputError = 65;     // EX_DATAERR
inline constexpr int kRunInternalError = 70;  // EX_SOFTWARE

/// The codes a command exits with when it fails for its usage, its input or itself.
struct FailureCodes {
  int usage = kInputError;
  int input = kInputError;
  int internal = kInternalError;
};

/// bipc, smcbip check|explore|monitor.
inline constexpr FailureCodes kJudgingCodes{kInputError, kInputError, kInternalError};
/// smcbip simulate, generated executables.
inline constexpr FailureCodes kRunCodes{kRunUsageError, kRunInputError, kRunInternalError};

}  // namespace smcbip::exit_codes
