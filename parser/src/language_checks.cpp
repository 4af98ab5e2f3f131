// What the grammar allows but the language does not: features of later
// versions (the gates of <safegi/lexer/extensions.hpp>) and qualifiers out of
// place. Each is reported and parsing goes on: no cascade, no ParseError.

#include "parser_impl.hpp"

namespace safegi::parser_detail {

using namespace ast;

void Parser::check_layout_id(const LayoutId& id) {
  if (!options_.language) return;
  // An atomic counter's offset is GLSL 4.20's (GL_ARB_shader_atomic_counters), a block member's 4.40's:
  // from 4.20 on the type decides, which the checker knows (validate_layouts.cpp).
  const bool typed_offset = id.name == "offset" && !options_.language->es && options_.language->version >= 420;
  if (std::string message = typed_offset ? "" : layout_id_requirement(id.name, *options_.language); !message.empty()) {
    diagnostics_.report(Diagnostic::error(id.name_range, std::move(message)).with_code(code::E_VERSION));
  }
  if (id.value && id.value->kind != NodeKind::LiteralExpr) {
    if (std::string message = layout_expression_requirement(*options_.language); !message.empty()) {
      diagnostics_.report(Diagnostic::error(id.value->range, std::move(message)).with_code(code::E_VERSION));
    }
  }
}

void Parser::check_layout_place(const TypeQualifiers& qualifiers, LayoutPlace place) {
  for (const Qualifier& q : qualifiers.list) {
    for (const LayoutId& id : q.layout_ids) {
      bool packing = id.name == "std140" || id.name == "std430" || id.name == "shared" || id.name == "packed";
      bool matrix = id.name == "row_major" || id.name == "column_major";
      if (packing) {
        diagnostics_.report(
            Diagnostic::error(id.name_range, "layout(" + id.name + ") applies to uniform and buffer blocks, not to " +
                                                 (place == LayoutPlace::Variable ? "variables" : "members"))
                .with_code(code::E_LAYOUT));
      } else if (matrix && place != LayoutPlace::BlockMember) {
        diagnostics_.report(
            Diagnostic::error(id.name_range, "layout(" + id.name +
                                                 ") applies to uniform and buffer blocks and their members, not to " +
                                                 (place == LayoutPlace::Variable ? "variables" : "struct members"))
                .with_code(code::E_LAYOUT));
      }
    }
  }
}

void Parser::check_sample(const TypeQualifiers& qualifiers, bool in_out) {
  for (const Qualifier& q : qualifiers.list) {
    if (q.word != "sample") continue;
    if (!in_out) {
      diagnostics_.report(Diagnostic::error(q.range, "'sample' applies only to 'in' and 'out' variables and blocks")
                              .with_code(code::E_QUALIFIER));
    } else if (qualifiers.has("centroid")) {
      diagnostics_.report(Diagnostic::error(q.range, "'sample' and 'centroid' cannot qualify the same declaration")
                              .with_code(code::E_QUALIFIER));
    }
  }
}

void Parser::require(LanguageFeature feature, SourceRange where) {
  if (!options_.language || options_.language->allows(feature)) return;
  diagnostics_.report(
      Diagnostic::error(where, feature_requirement(feature, options_.language->es)).with_code(code::E_VERSION));
}

}  // namespace safegi::parser_detail
