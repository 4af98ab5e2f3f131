#include "safegi/typechecker/checker.hpp"

#include <algorithm>

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

const std::vector<StageInfo>& stage_table() {
  static const std::vector<StageInfo> table = {
#define SAFEGI_STAGE(id, letter, extension, long_name, words, family) \
  {Stage::id, letter, extension, long_name, words, StageFamily::family},
#include "safegi/symbol_table/stages.def"
  };
  return table;
}

const StageInfo* stage_info(Stage stage) {
  for (const StageInfo& s : stage_table())
    if (s.stage == stage) return &s;
  return nullptr;
}

const char* stage_name(Stage stage) {
  const StageInfo* info = stage_info(stage);
  return info ? info->words : "unknown";
}

CheckResult check(const ast::TranslationUnit& unit, const CheckOptions& options, DiagnosticEngine& diagnostics) {
  CheckResult result;
  result.stage = options.stage;
  // Roughly one typed node per token: growing the map by rehashing cost a quarter of a large check.
  if (options.tokens) result.types.reserve(options.tokens->size());
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

namespace {

// Inputs of these stages (and outputs of tessellation control) carry one array
// level per vertex: `in vec3 n[]` in a geometry shader matches `out vec3 n`.
bool per_vertex_inputs(Stage s) { return s == Stage::geometry || s == Stage::tess_control || s == Stage::tess_evaluation; }

Type without_vertex_level(const InterfaceVariable& v, bool per_vertex) {
  if (!per_vertex || !v.block.empty() || !v.type.is_array()) return v.type;  // a block's array level is on its instance
  return v.type.element();
}

std::string member_name(const InterfaceVariable& v) {
  return v.block.empty() ? v.name : v.name.substr(v.name.rfind('.') + 1);
}

// The output an input reads, and how it was found ("" when there is none).
std::pair<const InterfaceVariable*, std::string> matching_output(const CheckResult& producer, const InterfaceVariable& in) {
  for (const InterfaceVariable& out : producer.interface) {
    if (out.kind != InterfaceKind::output) continue;
    if (!in.block.empty()) {
      if (out.block == in.block && member_name(out) == member_name(in)) return {&out, "block " + in.block};
    } else if (out.block.empty() && in.location >= 0) {
      if (out.location == in.location) return {&out, "location " + std::to_string(in.location)};
    }
  }
  if (!in.block.empty()) return {nullptr, ""};
  for (const InterfaceVariable& out : producer.interface)
    if (out.kind == InterfaceKind::output && out.block.empty() && out.name == in.name && (in.location < 0 || out.location < 0))
      return {&out, "name"};
  return {nullptr, ""};
}

}  // namespace

void check_interface_match(const CheckResult& producer, const CheckResult& consumer, DiagnosticEngine& diagnostics) {
  const bool consumer_per_vertex = per_vertex_inputs(consumer.stage);
  const bool producer_per_vertex = producer.stage == Stage::tess_control;
  for (const InterfaceVariable& in : consumer.interface) {
    if (in.kind != InterfaceKind::input) continue;
    auto [out, how] = matching_output(producer, in);
    if (!out) continue;
    const Type in_type = without_vertex_level(in, consumer_per_vertex);
    const Type out_type = without_vertex_level(*out, producer_per_vertex);
    if (in_type.is_error() || out_type.is_error()) continue;
    if (canonical(in_type, consumer.registry) == canonical(out_type, producer.registry)) continue;
    const std::string in_text = type_name(in_type, consumer.registry), out_text = type_name(out_type, producer.registry);
    const std::string producer_stage = producer.stage == Stage::unknown ? "previous" : stage_name(producer.stage);
    const std::string matched = how == "name" ? "" : " (matched by " + how + ")";
    diagnostics.report(Diagnostic::error(in.range, "input '" + in.name + "' has type " + in_text + " but the " + producer_stage +
                                                       " stage's output '" + out->name + "'" + matched + " has type " + out_text)
                           .with_code(code::E_STAGE_MISMATCH)
                           .with_note(Diagnostic::note(out->range, "output '" + out->name + "' declared here as " + out_text)));
  }
}

void check_payload_match(const CheckResult& tracer, const CheckResult& receiver, DiagnosticEngine& diagnostics) {
  std::vector<const InterfaceVariable*> traced;
  for (const InterfaceVariable& p : tracer.interface)
    if (p.kind == InterfaceKind::ray_payload && !p.type.is_error()) traced.push_back(&p);
  if (traced.empty()) return;
  for (const InterfaceVariable& in : receiver.interface) {
    if (in.kind != InterfaceKind::ray_payload_in || in.type.is_error()) continue;
    const auto same = [&](const InterfaceVariable* p) {
      return canonical(p->type, tracer.registry) == canonical(in.type, receiver.registry);
    };
    if (std::any_of(traced.begin(), traced.end(), same)) continue;
    const std::string in_text = type_name(in.type, receiver.registry);
    Diagnostic d = Diagnostic::error(in.range, "the " + std::string(stage_name(receiver.stage)) + " shader's payload '" +
                                                   in.name + "' has type " + in_text + ", but the " +
                                                   stage_name(tracer.stage) + " shader traces no payload of that type")
                       .with_code(code::E_STAGE_MISMATCH);
    for (const InterfaceVariable* p : traced)
      d.with_note(Diagnostic::note(p->range, "payload '" + p->name + "'" +
                                                 (p->location >= 0 ? " at location " + std::to_string(p->location) : "") +
                                                 " declared here as " + type_name(p->type, tracer.registry)));
    diagnostics.report(std::move(d));
  }
}

}  // namespace safegi
