// The checked/unchecked switch. Every typed name is declared once; SAFEGI_UNCHECKED
// only changes what the public aliases (quantity<D>, point<S>, ...) stand for.
//
// SAFEGI_DOUBLE=1 chooses the representation: every quantity, vector, spectrum
// and map then holds doubles (safegi::real), from the same source.
//
// Each mode lives in its own inline namespace (safegi::checked / safegi::unchecked,
// safegi::checked_double / safegi::unchecked_double), so object files built in
// different modes cannot link together silently: every function and type that
// carries a representation is mangled with its mode.
#pragma once

#if defined(SAFEGI_DOUBLE) && SAFEGI_DOUBLE
#define SAFEGI_TYPED_DOUBLE 1
#else
#define SAFEGI_TYPED_DOUBLE 0
#endif

#if defined(SAFEGI_UNCHECKED) && SAFEGI_UNCHECKED
#define SAFEGI_TYPED_CHECKED 0
#if SAFEGI_TYPED_DOUBLE
#define SAFEGI_MODE_NAMESPACE unchecked_double
#else
#define SAFEGI_MODE_NAMESPACE unchecked
#endif
#else
#define SAFEGI_TYPED_CHECKED 1
#if SAFEGI_TYPED_DOUBLE
#define SAFEGI_MODE_NAMESPACE checked_double
#else
#define SAFEGI_MODE_NAMESPACE checked
#endif
#endif

// Run-time checks the types cannot make (a direction's unit length): on in checked
// builds without NDEBUG, unless SAFEGI_CHECK_UNIT_LENGTH is defined first.
#ifndef SAFEGI_CHECK_UNIT_LENGTH
#if SAFEGI_TYPED_CHECKED && !defined(NDEBUG)
#define SAFEGI_CHECK_UNIT_LENGTH 1
#else
#define SAFEGI_CHECK_UNIT_LENGTH 0
#endif
#endif

namespace safegi {
inline namespace SAFEGI_MODE_NAMESPACE {
/// True when dimensions and spaces are checked (the default build).
inline constexpr bool is_checked = SAFEGI_TYPED_CHECKED != 0;
/// The representation of every typed value: float, or double with SAFEGI_DOUBLE=1.
#if SAFEGI_TYPED_DOUBLE
using real = double;
#else
using real = float;
#endif
}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi
