#pragma once
// Internal: the glad entry points are process globals; they are (re)loaded
// whenever a different context becomes current.
#include "platform.hpp"

namespace safegi::gl {

// Loads GL entry points for `owner` unless they are already loaded for it.
// Returns the loaded version as major*10+minor (0 on failure).
int load_gl_for(const Context::Backend* owner, GetProcAddress loader);
// Forgets `owner` (it is being destroyed).
void forget_gl_owner(const Context::Backend* owner);

}  // namespace safegi::gl
