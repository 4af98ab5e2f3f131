#pragma once
// Internal: the glad entry points are process globals; they are (re)loaded
// whenever a different context becomes current.
#include "platform.hpp"

namespace safegi::gl {

// Loads GL entry points for `owner` unless they are already loaded for it, and
// caps the version runtime_gl relies on at `cap` (major*10+minor): a context
// asked for 3.3 is used as 3.3 even when the driver offers more, so the 3.3
// code paths stay exercised. Returns the usable version (0 on failure).
int load_gl_for(const Context::Backend* owner, GetProcAddress loader, int cap);
// Forgets `owner` (it is being destroyed).
void forget_gl_owner(const Context::Backend* owner);

}  // namespace safegi::gl
