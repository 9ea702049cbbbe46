#pragma once
// Checked preconditions. Each public function states its preconditions in its comment
// ("Precondition: ..." / "Preconditions: ...") and asserts them on entry with SWEEP_EXPECTS,
// as meshoptimizer does. With SWEEP_CHECK_PRECONDITIONS (CMake option SWEEP_PRECONDITIONS, on in
// Debug, test and sanitizer builds) a failed check prints
//   sweep: precondition failed: TEXT (CONDITION) in FUNCTION at FILE:LINE
// to stderr and aborts; without it the check compiles to nothing (the condition is still
// type-checked, never evaluated), so Release builds pay nothing.
#include <cstdio>
#include <cstdlib>

namespace sweep::detail {

/// Reports a failed SWEEP_EXPECTS and aborts.
[[noreturn]] inline void precondition_failed(const char* text, const char* condition, const char* function,
                                             const char* file, int line) {
  std::fprintf(stderr, "sweep: precondition failed: %s (%s) in %s at %s:%d\n", text, condition, function, file, line);
  std::fflush(stderr);
  std::abort();
}

}  // namespace sweep::detail

#if defined(SWEEP_CHECK_PRECONDITIONS) && SWEEP_CHECK_PRECONDITIONS
#define SWEEP_EXPECTS(condition, text) \
  (static_cast<bool>(condition)        \
       ? static_cast<void>(0)          \
       : ::sweep::detail::precondition_failed(text, #condition, __func__, __FILE__, __LINE__))
#else
#define SWEEP_EXPECTS(condition, text) static_cast<void>(sizeof(static_cast<bool>(condition)))
#endif
