// Erasure (docs/language.md, "Erasure"): a list of byte edits on the user's
// files, applied in one pass per file. Every edit keeps the newlines of the
// bytes it replaces, so no line moves.

#include <algorithm>
#include <charconv>
#include <map>
#include <set>
#include <tuple>
#include <unordered_set>

#include <safegi/diagnostics/codes.hpp>

#include "safegi/elider/elider.hpp"
#include <safegi/parser/walk.hpp>

namespace safegi {
namespace {

using ast::walk;

struct Edit {
  std::uint32_t begin = 0;
  std::uint32_t end = 0;
  std::string text;
  // Orders zero-width insertions at one offset: closing text of inner
  // expressions first, then opening text of outer expressions first.
  std::int64_t order = 0;

  friend bool operator<(const Edit& a, const Edit& b) {
    return std::tie(a.begin, a.order, a.end, a.text) < std::tie(b.begin, b.order, b.end, b.text);
  }
};

// The line breaks of `text`, and the indentation after the last one, so a
// rewritten span that crossed lines still crosses them.
std::string newlines_of(std::string_view text) {
  std::string out;
  for (char c : text)
    if (c == '\n') out += c;
  if (const std::size_t last = text.find_last_of('\n'); last != std::string_view::npos) {
    std::string_view rest = text.substr(last + 1);
    out.append(rest.substr(0, rest.find_first_not_of(" \t")));
  }
  return out;
}

std::string blanked(std::string_view text) {
  std::string out(text);
  for (char& c : out)
    if (c != '\n' && c != '\r') c = ' ';
  return out;
}

std::string format_scale(double value) { return DimensionRegistry::format_number(value); }

// True when `text` holds no GLSL: a file of annotation declarations (the
// prelude) erases to comments and blanks, and its #include line then goes.
bool only_comments_and_space(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    if (text.compare(i, 2, "//") == 0) {
      i = text.find('\n', i);
      if (i == std::string_view::npos) return true;
    } else if (text.compare(i, 2, "/*") == 0) {
      const std::size_t end = text.find("*/", i + 2);
      if (end == std::string_view::npos) return true;
      i = end + 2;
    } else if (text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n') {
      ++i;
    } else {
      return false;
    }
  }
  return true;
}

bool is_primary(const ast::Expr* e) {
  switch (e->kind) {
    case ast::NodeKind::IdentifierExpr:
    case ast::NodeKind::LiteralExpr:
    case ast::NodeKind::CallExpr:
    case ast::NodeKind::IndexExpr:
    case ast::NodeKind::MemberExpr:
    case ast::NodeKind::MethodCallExpr:
    case ast::NodeKind::ParenExpr:
      return true;
    default:
      return false;
  }
}

// The GLSL text around the operands of one geometric operation. `wrap_a` /
// `wrap_b`: the operand needs parentheses unless it is a primary expression.
struct OperationShape {
  const char* prefix;
  const char* middle;
  const char* suffix;
  bool wrap_a;
  bool wrap_b;
};

const OperationShape* shape_of(GeometricOp op) {
  static const OperationShape point{"(", " * vec4(", ", 1.0)).xyz", true, false};
  static const OperationShape vector{"(mat3(", ") * ", ")", false, true};
  static const OperationShape normal{"(transpose(inverse(mat3(", "))) * ", ")", false, true};
  static const OperationShape project{"(", " * vec4(", ", 1.0))", true, false};
  static const OperationShape compose{"(", " * ", ")", true, true};
  switch (op) {
    case GeometricOp::transform_point: return &point;
    case GeometricOp::transform_vector: return &vector;
    case GeometricOp::transform_normal: return &normal;
    case GeometricOp::project: return &project;
    case GeometricOp::compose:
    case GeometricOp::transform_homogeneous: return &compose;
    default: return nullptr;
  }
}

// A SafeGI built-in of one argument that is no GLSL: a variable argument is written in place,
// any other argument goes through a helper emitted after #version, so it is evaluated once.
struct OneArgumentHelper {
  GeometricOp op;
  std::string_view name;      // the helper's name
  std::string_view inline_;   // the in-place text, with `@` for the variable
  std::string_view function;  // the helper's definition
};
constexpr OneArgumentHelper kHelpers[] = {
    {GeometricOp::homogenize, "safegi_homogenize", "(@.xyz / @.w)", "vec3 safegi_homogenize(vec4 h) { return h.xyz / h.w; }"},
    {GeometricOp::inverse_square, "safegi_inverse_square", "(1.0 / (@ * @))",
     "float safegi_inverse_square(float d) { return 1.0 / (d * d); }"},
};

class Eraser {
 public:
  Eraser(const ElideInput& input, DiagnosticEngine& diagnostics) : in_(input), diags_(diagnostics) {}

  ElideResult run() {
    collect_variable_names();
    walk(&in_.unit, [this](const ast::Node& n) { visit(n); });
    for (const auto& [node, info] : in_.checked.calls) geometric(*node, info);
    for (const auto& [node, info] : in_.checked.conversions) conversion(*node, info);
    ElideResult result;
    if (!in_.render) return result;
    result.source_files.push_back(in_.sources.path(in_.main_file));
    std::string text = render(in_.main_file, 0, result.source_files);
    result.glsl = with_preamble(std::move(text));
    result.helpers.assign(helpers_.begin(), helpers_.end());
    return result;
  }

 private:
  void collect_variable_names() {
    walk(&in_.unit, [this](const ast::Node& n) {
      if (auto* v = ast::dyn_cast<ast::VariableDecl>(&n))
        for (const ast::Declarator& d : v->declarators) variables_.insert(d.name);
      else if (auto* p = ast::dyn_cast<ast::ParamDecl>(&n))
        variables_.insert(p->name);
      else if (auto* b = ast::dyn_cast<ast::InterfaceBlockDecl>(&n))
        variables_.insert(b->instance_name);
    });
  }

  std::string_view text_of(FileId file, std::uint32_t begin, std::uint32_t end) const {
    std::string_view text = in_.sources.text(file);
    if (begin > end || end > text.size()) return {};
    return text.substr(begin, end - begin);
  }

  void add(const SourceRange& range, std::string text, std::int64_t order = 0) {
    if (!range.valid() || range.end.offset < range.begin.offset) return;
    edits_[range.begin.file].insert(Edit{range.begin.offset, range.end.offset, std::move(text), order});
  }
  void add(FileId file, std::uint32_t begin, std::uint32_t end, std::string text, std::int64_t order) {
    edits_[file].insert(Edit{begin, end, std::move(text), order});
  }

  void blank(const SourceRange& range) {
    add(range, blanked(text_of(range.begin.file, range.begin.offset, range.end.offset)));
  }

  // `text` in place of `range`, padded with spaces so later columns stay put
  // where it fits, newlines of the range kept.
  void replace_padded(const SourceRange& range, std::string text) {
    std::string_view old = text_of(range.begin.file, range.begin.offset, range.end.offset);
    std::string kept = newlines_of(old);
    if (text.size() + kept.size() < old.size()) text.append(old.size() - text.size() - kept.size(), ' ');
    add(range, text + kept);
  }

  void visit(const ast::Node& n) {
    switch (n.kind) {
      case ast::NodeKind::DimensionDecl:
      case ast::NodeKind::UnitDecl:
      case ast::NodeKind::SpaceDecl:
        blank(n.range);
        return;
      case ast::NodeKind::FunctionDecl: {
        auto& f = static_cast<const ast::FunctionDecl&>(n);
        if (!f.template_params.empty() || f.template_range.valid()) blank(f.template_range);
        return;
      }
      case ast::NodeKind::TypeSpecifier: {
        auto& t = static_cast<const ast::TypeSpecifier&>(n);
        if (t.annotation == nullptr) return;
        if (t.form == ast::TypeSpecifier::Form::Annotated) {
          SourceRange whole{t.name_range.begin, t.annotation->range.end};
          replace_padded(whole, std::string(ast::annotated_type_representation(t.name)));
        } else {
          blank(t.annotation->range);
        }
        return;
      }
      case ast::NodeKind::CallExpr:
        return cast(static_cast<const ast::CallExpr&>(n));
      case ast::NodeKind::BinaryExpr:
        return unit_factor(static_cast<const ast::BinaryExpr&>(n));
      case ast::NodeKind::IdentifierExpr: {
        auto& e = static_cast<const ast::IdentifierExpr&>(n);
        if (variables_.count(e.name) || erased_units_.count(&e)) return;
        if (const Unit* unit = in_.checked.registry.find_unit(e.name))
          replace_padded(e.range, "(" + format_scale(unit->scale) + ")");
        return;
      }
      default:
        return;
    }
  }

  // A cast that only changes the annotation (`float<solid_angle>(x)` of a
  // float x) erases to parentheses: the plain constructor would be a no-op a
  // careful programmer does not write.
  void cast(const ast::CallExpr& call) {
    const ast::TypeSpecifier* t = call.constructor_type;
    if (t == nullptr || t->annotation == nullptr || !t->array_dims.empty() || call.args.size() != 1) return;
    const Type* result = in_.checked.type_of(&call);
    const Type* arg = in_.checked.type_of(call.args[0]);
    if (result == nullptr || arg == nullptr || result->is_error() || !same_glsl_type(*result, *arg)) return;
    SourceRange word{t->name_range.begin, t->annotation->range.end};
    add(word, blanked(text_of(word.begin.file, word.begin.offset, word.end.offset)), -1);
  }

  void geometric(const ast::Node& node, const CallInfo& info) {
    const ast::Expr* a = nullptr;
    const ast::Expr* b = nullptr;
    if (auto* bin = ast::dyn_cast<ast::BinaryExpr>(&node)) {
      if (info.op == GeometricOp::compose || info.op == GeometricOp::transform_homogeneous) return;  // already GLSL
      a = bin->lhs;
      b = bin->rhs;
    } else if (auto* call = ast::dyn_cast<ast::CallExpr>(&node)) {
      for (const OneArgumentHelper& h : kHelpers)
        if (info.op == h.op && call->args.size() == 1) return one_argument(*call, h);
      if (call->args.size() != 2) return;
      a = call->args[0];
      b = call->args[1];
    } else {
      return;
    }
    const OperationShape* shape = shape_of(info.op);
    if (shape == nullptr || a == nullptr || b == nullptr) return;
    const SourceRange& w = node.range;
    const FileId file = w.begin.file;
    const bool in_order = a->range.begin.file == file && b->range.begin.file == file && a->range.end.file == file &&
                          b->range.end.file == file && w.end.file == file && w.begin.offset <= a->range.begin.offset &&
                          a->range.begin.offset <= a->range.end.offset && a->range.end.offset <= b->range.begin.offset &&
                          b->range.begin.offset <= b->range.end.offset && b->range.end.offset <= w.end.offset;
    if (!in_order) return cannot_rewrite(node);
    const bool pa = shape->wrap_a && !is_primary(a);
    const bool pb = shape->wrap_b && !is_primary(b);
    const std::int64_t size = w.end.offset - w.begin.offset;
    auto gap = [&](std::uint32_t from, std::uint32_t to, std::string text, std::int64_t order) {
      add(file, from, to, text + newlines_of(text_of(file, from, to)), order);
    };
    gap(w.begin.offset, a->range.begin.offset, std::string(shape->prefix) + (pa ? "(" : ""), -size);
    gap(a->range.end.offset, b->range.begin.offset,
        std::string(pa ? ")" : "") + shape->middle + (pb ? "(" : ""), 0);
    gap(b->range.end.offset, w.end.offset, std::string(pb ? ")" : "") + shape->suffix, -(1LL << 40) + size);
  }

  // `e in target`: a unit conversion is `(e * factor)` (nothing when the factor
  // is 1); a space conversion is the maps' product applied the way transform()
  // applies one map, `(viewFromWorld * worldFromObject * vec4(p, 1.0)).xyz`.
  void conversion(const ast::ConvertExpr& e, const ConversionInfo& info) {
    const SourceRange& w = e.range;
    const SourceRange& a = e.operand->range;
    const FileId file = w.begin.file;
    if (a.begin.file != file || a.end.file != file || w.end.file != file || a.begin.offset != w.begin.offset ||
        a.end.offset > w.end.offset)
      return cannot_rewrite(e);
    const std::int64_t size = w.end.offset - w.begin.offset;
    auto around = [&](const std::string& prefix, const std::string& suffix) {
      if (!prefix.empty()) add(file, w.begin.offset, w.begin.offset, prefix, -size);
      add(file, a.end.offset, w.end.offset, suffix + newlines_of(text_of(file, a.end.offset, w.end.offset)), -(1LL << 40) + size);
    };
    if (info.maps.empty()) {
      if (DimensionRegistry::same_scale(info.factor, 1.0)) return around("", "");
      return around("(", " * " + format_scale(info.factor) + ")");
    }
    std::string maps;
    for (const std::string& m : info.maps) maps += (maps.empty() ? "" : " * ") + m;
    switch (info.op) {
      case GeometricOp::transform_point: return around("(" + maps + " * vec4(", ", 1.0)).xyz");
      case GeometricOp::transform_homogeneous: return around("(" + maps + " * ", ")");
      case GeometricOp::project: return around("(" + maps + " * vec4(", ", 1.0))");
      case GeometricOp::transform_normal: return around("(transpose(inverse(mat3(" + maps + "))) * ", ")");
      default: return around("(mat3(" + maps + ") * ", ")");
    }
  }

  // `homogenize(h)`: `(h.xyz / h.w)` for a variable, else a helper call so
  // that `h` is evaluated once; `inverse_square(d)` likewise.
  void one_argument(const ast::CallExpr& call, const OneArgumentHelper& helper) {
    const ast::Expr* x = call.args[0];
    if (auto* id = ast::dyn_cast<ast::IdentifierExpr>(x); id && call.range.begin.file == call.range.end.file) {
      std::string_view old = text_of(call.range.begin.file, call.range.begin.offset, call.range.end.offset);
      std::string text;
      for (char c : helper.inline_) text += c == '@' ? id->name : std::string(1, c);
      add(call.range, text + newlines_of(old));
      return;
    }
    helpers_.insert(std::string(helper.name));
    replace_padded(call.callee_range, std::string(helper.name));
  }

  // A unit of scale 1 as a factor (`2.0 * meter`, `d / meter`, `meter * d`) is erased with
  // its operator, so the checked shader compiles to the instructions of the plain one (glslang
  // folds no `x / (1.0)`); anywhere else a unit is its scale, `(1.0)`.
  const ast::IdentifierExpr* unit_of_scale_one(const ast::Expr* e) const {
    auto* id = ast::dyn_cast<ast::IdentifierExpr>(e);
    if (id == nullptr || variables_.count(id->name)) return nullptr;
    const Unit* unit = in_.checked.registry.find_unit(id->name);
    return unit != nullptr && DimensionRegistry::same_scale(unit->scale, 1.0) ? id : nullptr;
  }
  void unit_factor(const ast::BinaryExpr& e) {
    if ((e.op != ast::BinaryOp::Mul && e.op != ast::BinaryOp::Div) || e.lhs == nullptr || e.rhs == nullptr) return;
    const SourceRange& l = e.lhs->range;
    const SourceRange& r = e.rhs->range;
    const FileId file = l.begin.file;
    if (l.end.file != file || r.begin.file != file || r.end.file != file || l.end.offset > r.begin.offset) return;
    if (const ast::IdentifierExpr* unit = unit_of_scale_one(e.rhs)) {
      erased_units_.insert(unit);
      add(file, l.end.offset, r.end.offset, blanked(text_of(file, l.end.offset, r.end.offset)), 0);
    } else if (e.op == ast::BinaryOp::Mul && (unit = unit_of_scale_one(e.lhs)) != nullptr) {
      erased_units_.insert(unit);
      add(file, l.begin.offset, r.begin.offset, blanked(text_of(file, l.begin.offset, r.begin.offset)), 0);
    }
  }

  void cannot_rewrite(const ast::Node& node) {
    diags_.report(Diagnostic::error(node.range, "cannot erase this geometric operation: its operands come from "
                                                "different macro expansions")
                      .with_code(code::E_ELIDE_MACRO)
                      .with_hint("write the operation outside the macro, or make the macro expand to the whole operation"));
  }

  std::string apply(FileId file, std::vector<Edit> extra) const {
    std::string_view text = in_.sources.text(file);
    std::vector<Edit> edits = std::move(extra);
    if (auto it = edits_.find(file); it != edits_.end()) edits.insert(edits.end(), it->second.begin(), it->second.end());
    std::stable_sort(edits.begin(), edits.end(), [](const Edit& x, const Edit& y) {
      if (x.begin != y.begin) return x.begin < y.begin;
      const bool xz = x.begin == x.end, yz = y.begin == y.end;
      if (xz != yz) return xz;  // insertions before a replacement at the same offset
      if (x.order != y.order) return x.order < y.order;
      return x.end > y.end;     // the outer replacement wins
    });
    std::string out;
    out.reserve(text.size() + 64);
    std::uint32_t cursor = 0;
    for (const Edit& e : edits) {
      if (e.begin < cursor || e.end > text.size()) continue;  // inside a region already replaced
      out.append(text.substr(cursor, e.begin - cursor));
      out += e.text;
      cursor = e.end;
    }
    out.append(text.substr(std::min<std::size_t>(cursor, text.size())));
    return out;
  }

  // `#line N` makes the next line N from GLSL 3.30 / ES 3.00 on, N + 1 before.
  std::uint32_t line_directive_number(std::uint32_t next_line) const {
    const bool old_semantics = !in_.preprocessed.es && in_.preprocessed.version != 100 && in_.preprocessed.version < 330;
    return old_semantics ? next_line - 1 : next_line;
  }

  std::string render(FileId file, std::size_t source_string, std::vector<std::string>& source_files) const {
    std::vector<Edit> includes;
    for (const IncludedFile& inc : in_.preprocessed.includes) {
      if (inc.directive.begin.file != file) continue;
      const std::size_t index = source_files.size();
      source_files.push_back(inc.path);
      std::string body = render(inc.file, index, source_files);
      std::string_view directive = text_of(file, inc.directive.begin.offset, inc.directive.end.offset);
      if (only_comments_and_space(body)) {
        // Only annotation declarations (the prelude): the #include line goes.
        source_files.resize(index);
        includes.push_back(Edit{inc.directive.begin.offset, inc.directive.end.offset, blanked(directive), 0});
        continue;
      }
      if (body.empty() || body.back() != '\n') body += '\n';
      const std::uint32_t next = inc.directive.end.line + 1;
      includes.push_back(Edit{inc.directive.begin.offset, inc.directive.end.offset,
                              "#line " + std::to_string(line_directive_number(1)) + " " + std::to_string(index) + "\n" +
                                  body + "#line " + std::to_string(line_directive_number(next)) + " " +
                                  std::to_string(source_string),
                              0});
    }
    return apply(file, std::move(includes));
  }

  std::string with_preamble(std::string text) const {
    std::string lines;
    for (const auto& [name, value] : in_.defines) lines += "#define " + name + (value.empty() ? "" : " " + value) + "\n";
    for (const std::string& name : in_.undefines) lines += "#undef " + name + "\n";
    for (const OneArgumentHelper& h : kHelpers)
      if (helpers_.count(std::string(h.name))) lines += std::string(h.function) + "\n";
    if (lines.empty()) return text;
    const SourceRange& version = in_.preprocessed.version_range;
    if (in_.preprocessed.version_given && version.begin.file == in_.main_file) {
      // After the #version line (whose newline stays where it was).
      const std::size_t at = version.end.offset;
      if (at > text.size()) return text;
      lines.pop_back();
      return text.substr(0, at) + "\n" + lines + "\n#line " +
             std::to_string(line_directive_number(version.end.line + 1)) + text.substr(at);
    }
    return lines + "#line " + std::to_string(line_directive_number(1)) + "\n" + text;
  }

  const ElideInput& in_;
  DiagnosticEngine& diags_;
  std::unordered_set<std::string> variables_;
  std::map<FileId, std::set<Edit>> edits_;
  std::set<std::string> helpers_;
  std::set<const ast::Node*> erased_units_;  // units erased with their operator (unit_factor)
};

}  // namespace

ElideResult elide(const ElideInput& input, DiagnosticEngine& diagnostics) {
  return Eraser(input, diagnostics).run();
}

std::string source_hash(std::string_view text) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  static const char* digits = "0123456789abcdef";
  std::string out = "fnv1a64:";
  for (int shift = 60; shift >= 0; shift -= 4) out += digits[(h >> shift) & 0xf];
  return out;
}

}  // namespace safegi
