// The checked/unchecked switch. Every typed name is declared once; SAFEGI_UNCHECKED
// only changes what the public aliases (quantity<D>, point<S>, ...) stand for.
//
// Each mode lives in its own inline namespace (safegi::checked / safegi::unchecked),
// so object files built in different modes cannot link together silently: every
// function and type that carries a representation is mangled with its mode.
#pragma once

#if defined(SAFEGI_UNCHECKED) && SAFEGI_UNCHECKED
#define SAFEGI_TYPED_CHECKED 0
#define SAFEGI_MODE_NAMESPACE unchecked
#else
#define SAFEGI_TYPED_CHECKED 1
#define SAFEGI_MODE_NAMESPACE checked
#endif

namespace safegi {
inline namespace SAFEGI_MODE_NAMESPACE {
/// True when dimensions and spaces are checked (the default build).
inline constexpr bool is_checked = SAFEGI_TYPED_CHECKED != 0;
}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi
