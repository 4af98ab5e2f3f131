#include "safegi/typechecker/checker.hpp"

#include "checker_impl.hpp"
#include "dim_slot.hpp"

namespace safegi {

const Type* CheckResult::type_of(const ast::Node* node) const {
  auto it = types.find(node);
  return it == types.end() ? nullptr : &it->second;
}

const Type* CheckResult::type_of(const ast::Declarator* declarator) const {
  auto it = declarators.find(declarator);
  return it == declarators.end() ? nullptr : &it->second;
}

const char* stage_name(Stage stage) {
  switch (stage) {
    case Stage::vertex: return "vertex";
    case Stage::tess_control: return "tessellation control";
    case Stage::tess_evaluation: return "tessellation evaluation";
    case Stage::geometry: return "geometry";
    case Stage::fragment: return "fragment";
    case Stage::compute: return "compute";
    case Stage::unknown: break;
  }
  return "unknown";
}

CheckResult check(const ast::TranslationUnit& unit, const CheckOptions& options, DiagnosticEngine& diagnostics) {
  CheckResult result;
  detail::Checker checker(options, diagnostics, result);
  checker.run(unit);
  return result;
}

namespace {

// Types are compared by their printed form in each program's own words, so two
// stages that declare the same vocabulary (the prelude) compare equal.
std::string canonical(const Type& t, const DimensionRegistry& registry) {
  Type c = t;
  c.dim.spelling.clear();
  std::string out = glsl_name(c) + "|" + geometry_name(c.geometry) + "|";
  if (c.dim.is_known()) out += registry.format_product(c.dim.value, Notation::ascii);
  out += "|" + (c.from.is_known() ? registry.space_name(c.from.id) : std::string("?"));
  out += "|" + (c.to.is_known() ? registry.space_name(c.to.id) : std::string("?"));
  return out;
}

}  // namespace

void check_interface_match(const CheckResult& producer, const CheckResult& consumer, DiagnosticEngine& diagnostics) {
  for (const InterfaceVariable& in : consumer.interface) {
    if (in.kind != InterfaceKind::input) continue;
    for (const InterfaceVariable& out : producer.interface) {
      if (out.kind != InterfaceKind::output || out.name != in.name) continue;
      if (canonical(in.type, consumer.registry) == canonical(out.type, producer.registry)) continue;
      diagnostics.report(Diagnostic::error(in.range, "input '" + in.name + "' has type " + in.type_text +
                                                         " but the previous stage's output has type " + out.type_text)
                             .with_code("E-STAGE-MISMATCH")
                             .with_note(Diagnostic::note(out.range, "output '" + out.name + "' declared here as " + out.type_text)));
    }
  }
}

}  // namespace safegi
