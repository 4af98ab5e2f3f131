#pragma once
// Everything of runtime_gl: contexts, symbol tables, programs with typed
// lookups, typed buffers, textures and framebuffers.
#include "safegi/runtime_gl/context.hpp"
#include "safegi/symbol_table/error.hpp"
#include "safegi/runtime_gl/handles.hpp"
#include "safegi/runtime_gl/program.hpp"
#include "safegi/runtime_gl/resources.hpp"
#include "safegi/symbol_table/symbol_table.hpp"
#include "safegi/symbol_table/value_traits.hpp"
// With the typed library on the include path (SafeGI::runtime_gl links it),
// its types are GL values too.
#if __has_include(<safegi/typed.hpp>)
#include "safegi/symbol_table/typed_traits.hpp"
#endif
