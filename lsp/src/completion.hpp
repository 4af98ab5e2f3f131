#pragma once
// Completion of annotation names: dimensions where a dimension is expected
// (`float<`, `spectrum<`, `vector<world, `, `dimension x = `, `unit u : `),
// spaces where a space is (`point<`, `map<a, `), annotated types in a
// sampler's `<`, `dimension`/`space` in `template<`, and units after `*` or
// `/` in an expression (`3.0 * cent`).
//
// The names come from the document's current text, preprocessed (the prelude
// and other includes) and scanned for declarations — not from the checker,
// which cannot run on the half-typed `float<` being completed. Template
// parameters are offered inside their function.

#include <cstddef>
#include <string>
#include <vector>
#include <string_view>

#include <safegi/compiler/compile.hpp>

#include "protocol.hpp"

namespace safegi::lsp {

enum class Expected { nothing, dimension, space, type, template_parameter_kind, unit, orientation };

struct CompletionContext {
  Expected expected = Expected::nothing;
  std::vector<std::string> orientations;  // away, toward or shaded, where one may end the annotation
  std::string prefix;  // the part of a name already typed before the cursor
};

// What is expected at byte `offset` of `text`.
CompletionContext completion_context(std::string_view text, std::size_t offset);

// The CompletionList at `offset` of `text` (the document at `path`), details
// from `registry` when there is one (the last checked analysis).
json completion(const std::string& path, const std::string& text, std::size_t offset, const CompileOptions& options,
                const DimensionRegistry* registry);

}  // namespace safegi::lsp
