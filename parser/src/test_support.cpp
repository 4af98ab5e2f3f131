#include "test_support.hpp"

#include <mutex>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <safegi/diagnostics/render.hpp>
#include <safegi/lexer/lexer.hpp>

namespace safegi::testing {

std::string Parsed::errors() const { return render_text(diagnostics.diagnostics(), sources); }

std::string Parsed::glsl(bool annotations) const {
  PrintOptions options;
  options.annotations = annotations;
  return print_glsl(*result.unit, options);
}

std::unique_ptr<Parsed> parse_text(std::string_view source, ParseOptions options) {
  auto parsed = std::make_unique<Parsed>();
  FileId file = parsed->sources.add_file("test.glsl", std::string(source));
  parsed->tokens = tokenize(parsed->sources, file, parsed->diagnostics);
  parsed->result = parse(parsed->tokens, parsed->diagnostics, options);
  return parsed;
}

std::string dump_first(std::string_view source) {
  auto parsed = parse_text(source);
  if (parsed->diagnostics.has_errors()) return parsed->errors();
  const auto& decls = parsed->unit().decls;
  if (decls.empty()) return "";
  if (const auto* fn = ast::dyn_cast<ast::FunctionDecl>(decls.front()); fn && fn->body &&
                                                                        !fn->body->statements.empty()) {
    return dump_ast(*fn->body->statements.front());
  }
  return dump_ast(*decls.front());
}

std::string dump_expr(std::string_view source) {
  auto parsed = parse_text("void f() { t = " + std::string(source) + "; }");
  if (parsed->diagnostics.has_errors()) return parsed->errors();
  const auto* fn = ast::dyn_cast<ast::FunctionDecl>(parsed->unit().decls.front());
  const auto* stmt = ast::dyn_cast<ast::ExprStmt>(fn->body->statements.front());
  return dump_ast(*ast::dyn_cast<ast::AssignExpr>(stmt->expr)->rhs);
}

namespace {

EShLanguage stage_of(std::string_view stage) {
  if (stage == "vert") return EShLangVertex;
  if (stage == "comp") return EShLangCompute;
  if (stage == "geom") return EShLangGeometry;
  if (stage == "tesc") return EShLangTessControl;
  if (stage == "tese") return EShLangTessEvaluation;
  return EShLangFragment;
}

}  // namespace

bool glslang_accepts(const std::string& glsl, std::string_view stage, std::string* log) {
  static std::once_flag init;
  std::call_once(init, [] { glslang::InitializeProcess(); });
  glslang::TShader shader(stage_of(stage));
  const char* text = glsl.c_str();
  shader.setStrings(&text, 1);
  bool ok = shader.parse(GetDefaultResources(), 100, false, EShMsgDefault);
  if (!ok && log) *log = std::string(shader.getInfoLog()) + "\n--- source ---\n" + glsl;
  return ok;
}

}  // namespace safegi::testing
