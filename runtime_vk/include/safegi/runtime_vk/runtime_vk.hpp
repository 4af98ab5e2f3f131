#pragma once
// Everything of runtime_vk: the headless context, typed buffers and images,
// compute pipelines bound by the symbol table.
#include "safegi/runtime_vk/context.hpp"
#include "safegi/runtime_vk/handles.hpp"
#include "safegi/runtime_vk/layout.hpp"
#include "safegi/runtime_vk/pipeline.hpp"
#include "safegi/runtime_vk/resources.hpp"
// With the typed library on the include path (SafeGI::runtime_vk links it),
// its types are GPU values too.
#if __has_include(<safegi/typed.hpp>)
#include "safegi/symbol_table/typed_traits.hpp"
#endif
