// #if expressions: every C operator GLSL's preprocessor allows, evaluated as
// GLSL's 32-bit int (two's complement, wrapping, as glslang does) without
// undefined behaviour, with short-circuit evaluation so `0 && 1 / 0` is not
// an error. An undefined macro in ES is an error where glslang evaluates it
// (`quiet`: glslang's shortCircuit, below).

#include <string>

#include <safegi/diagnostics/codes.hpp>

#include "preprocessor_internal.hpp"

namespace safegi::detail {
namespace {

class ExpressionEvaluator {
 public:
  ExpressionEvaluator(const std::vector<Token>& tokens, SourceRange directive, const ExpressionContext& context,
                      DiagnosticEngine& diagnostics)
      : tokens_(tokens), directive_(directive), context_(context), diagnostics_(diagnostics) {}

  std::optional<std::int64_t> run() {
    if (tokens_.empty()) {
      fail(code::E_PP_EXPRESSION, directive_, "expected an expression after the directive");
      return std::nullopt;
    }
    std::int64_t value = binary(0, true, false);
    if (!failed_ && pos_ < tokens_.size()) {
      fail(code::E_PP_EXPRESSION, tokens_[pos_].range,
           "unexpected " + describe(tokens_[pos_]) + " in preprocessor expression");
    }
    if (failed_) return std::nullopt;
    return value;
  }

 private:
  static std::string describe(const Token& t) {
    if (t.kind == TokenKind::identifier || is_numeric_literal(t.kind)) return "'" + std::string(t.text) + "'";
    return std::string(token_kind_description(t.kind));
  }

  void fail(const char* code, SourceRange range, std::string message, ExpansionId expansion = kNoExpansion) {
    if (failed_) return;
    failed_ = true;
    diagnostics_.report(Diagnostic::error(range, std::move(message)).with_code(code).with_expansion(expansion));
  }

  const Token* peek() const { return pos_ < tokens_.size() ? &tokens_[pos_] : nullptr; }

  SourceRange end_range() const {
    return tokens_.empty() ? directive_ : SourceRange{tokens_.back().range.end, tokens_.back().range.end};
  }

  // Binding power of a binary operator; 0 if the token is not one.
  static int precedence(TokenKind kind) {
    switch (kind) {
      case TokenKind::pipe_pipe: return 1;
      case TokenKind::amp_amp: return 2;
      case TokenKind::pipe: return 3;
      case TokenKind::caret: return 4;
      case TokenKind::amp: return 5;
      case TokenKind::equal_equal:
      case TokenKind::bang_equal: return 6;
      case TokenKind::less:
      case TokenKind::greater:
      case TokenKind::less_equal:
      case TokenKind::greater_equal: return 7;
      case TokenKind::less_less:
      case TokenKind::greater_greater: return 8;
      case TokenKind::plus:
      case TokenKind::minus: return 9;
      case TokenKind::star:
      case TokenKind::slash:
      case TokenKind::percent: return 10;
      default: return 0;
    }
  }

  static std::int64_t wrap(std::uint64_t v) { return static_cast<std::int32_t>(static_cast<std::uint32_t>(v)); }

  // Precedence climbing; `evaluated` is false on the unevaluated side of && / ||.
  // `quiet` is glslang's shortCircuit (TPpContext::eval), which decides where an
  // undefined macro is an ES error: set after `&&` whose left side is 0 or `||`
  // whose left side is exactly 1, it then stays set for the rest of this level's
  // operators (`0 && X || Y` never reports Y; `2 || X` reports X).
  std::int64_t binary(int min_precedence, bool evaluated, bool quiet) {
    std::int64_t lhs = unary(evaluated, quiet);
    while (!failed_) {
      const Token* op = peek();
      if (!op) break;
      int p = precedence(op->kind);
      if (p == 0 || p <= min_precedence) break;
      ++pos_;
      TokenKind kind = op->kind;
      bool rhs_evaluated = evaluated;
      if (kind == TokenKind::amp_amp) rhs_evaluated = evaluated && lhs != 0;
      if (kind == TokenKind::pipe_pipe) rhs_evaluated = evaluated && lhs == 0;
      if ((kind == TokenKind::amp_amp && lhs == 0) || (kind == TokenKind::pipe_pipe && lhs == 1)) quiet = true;
      std::int64_t rhs = binary(p, rhs_evaluated, quiet);
      if (failed_) break;
      lhs = apply(kind, lhs, rhs, *op, rhs_evaluated);
    }
    return lhs;
  }

  std::int64_t apply(TokenKind kind, std::int64_t a, std::int64_t b, const Token& op, bool evaluated) {
    auto ua = static_cast<std::uint64_t>(a);
    auto ub = static_cast<std::uint64_t>(b);
    switch (kind) {
      case TokenKind::pipe_pipe: return (a != 0 || b != 0) ? 1 : 0;
      case TokenKind::amp_amp: return (a != 0 && b != 0) ? 1 : 0;
      case TokenKind::pipe: return wrap(ua | ub);
      case TokenKind::caret: return wrap(ua ^ ub);
      case TokenKind::amp: return wrap(ua & ub);
      case TokenKind::equal_equal: return a == b;
      case TokenKind::bang_equal: return a != b;
      case TokenKind::less: return a < b;
      case TokenKind::greater: return a > b;
      case TokenKind::less_equal: return a <= b;
      case TokenKind::greater_equal: return a >= b;
      case TokenKind::plus: return wrap(ua + ub);
      case TokenKind::minus: return wrap(ua - ub);
      case TokenKind::star: return wrap(ua * ub);
      case TokenKind::less_less:
      case TokenKind::greater_greater:
        if (b < 0 || b > 31) {
          if (evaluated)
            fail(code::E_PP_EXPRESSION, op.range, "shift count " + std::to_string(b) + " is out of range",
                 op.expansion);
          return 0;
        }
        return kind == TokenKind::less_less ? wrap(ua << b) : wrap(static_cast<std::uint64_t>(a >> b));
      case TokenKind::slash:
      case TokenKind::percent:
        if (b == 0) {
          if (evaluated) {
            fail(code::E_PP_EXPRESSION, op.range,
                 kind == TokenKind::slash ? "division by zero in preprocessor expression"
                                          : "remainder by zero in preprocessor expression",
                 op.expansion);
          }
          return 0;
        }
        if (a == INT32_MIN && b == -1) return 0;  // overflows; glslang yields 0
        return wrap(static_cast<std::uint64_t>(kind == TokenKind::slash ? a / b : a % b));
      default: return 0;
    }
  }

  std::int64_t unary(bool evaluated, bool quiet) {
    if (++depth_ > context_.max_depth) {
      fail(code::E_LIMIT, peek() ? peek()->range : end_range(), "preprocessor expression nested too deeply");
      return 0;
    }
    struct DepthGuard {
      int& depth;
      ~DepthGuard() { --depth; }
    } guard{depth_};
    const Token* t = peek();
    if (!t) {
      fail(code::E_PP_EXPRESSION, end_range(), "expected a value at the end of the preprocessor expression");
      return 0;
    }
    ++pos_;
    switch (t->kind) {
      case TokenKind::plus: return unary(evaluated, quiet);
      case TokenKind::minus: return wrap(0 - static_cast<std::uint64_t>(unary(evaluated, quiet)));
      case TokenKind::tilde: return wrap(~static_cast<std::uint64_t>(unary(evaluated, quiet)));
      case TokenKind::bang: return unary(evaluated, quiet) == 0 ? 1 : 0;
      case TokenKind::l_paren: {
        std::int64_t value = binary(0, evaluated, quiet);
        if (failed_) return 0;
        const Token* close = peek();
        if (!close || close->kind != TokenKind::r_paren) {
          fail(code::E_PP_EXPRESSION, close ? close->range : end_range(), "expected ')' in preprocessor expression");
          return 0;
        }
        ++pos_;
        return value;
      }
      case TokenKind::int_literal:
      case TokenKind::uint_literal:
      case TokenKind::int64_literal:
      case TokenKind::uint64_literal:
      case TokenKind::int16_literal:
      case TokenKind::uint16_literal: {
        if (NumericLiteralCheck check = check_numeric_literal(t->text); !check.error.empty()) {
          fail(code::E_LITERAL, t->range, check.error, t->expansion);
          return 0;
        }
        auto value = integer_literal_value(t->text);
        if (!value) {
          fail(code::E_LITERAL, t->range, "invalid integer literal '" + std::string(t->text) + "'", t->expansion);
          return 0;
        }
        return wrap(*value);
      }
      case TokenKind::float_literal:
      case TokenKind::double_literal:
      case TokenKind::float16_literal:
        fail(code::E_PP_EXPRESSION, t->range,
             "floating-point literal '" + std::string(t->text) + "' in preprocessor expression", t->expansion);
        return 0;
      case TokenKind::identifier:
        if (t->text == "true" || t->text == "false") {
          fail(code::E_PP_EXPRESSION, t->range,
               "'" + std::string(t->text) + "' is not allowed in a preprocessor expression (use 1 or 0)", t->expansion);
          return 0;
        }
        if (context_.es && !quiet) {
          fail(code::E_PP_EXPRESSION, t->range,
               "'" + std::string(t->text) + "' is not defined (undefined macros are errors in #if in ES)",
               t->expansion);
          return 0;
        }
        if (evaluated) {
          diagnostics_.report(
              Diagnostic::warning(t->range, "'" + std::string(t->text) + "' is not defined, evaluates to 0")
                  .with_code(code::W_UNDEFINED_MACRO)
                  .with_expansion(t->expansion));
        }
        return 0;
      default:
        fail(code::E_PP_EXPRESSION, t->range, "expected a value in preprocessor expression, found " + describe(*t),
             t->expansion);
        return 0;
    }
  }

  const std::vector<Token>& tokens_;
  SourceRange directive_;
  const ExpressionContext& context_;
  DiagnosticEngine& diagnostics_;
  std::size_t pos_ = 0;
  int depth_ = 0;
  bool failed_ = false;
};

}  // namespace

std::optional<std::int64_t> evaluate_expression(const std::vector<Token>& tokens, SourceRange directive,
                                                const ExpressionContext& context, DiagnosticEngine& diagnostics) {
  return ExpressionEvaluator(tokens, directive, context, diagnostics).run();
}

bool Macro::same_definition(const Macro& other) const {
  if (function_like != other.function_like || params != other.params || body.size() != other.body.size()) {
    return false;
  }
  for (std::size_t i = 0; i < body.size(); ++i) {
    if (body[i].text != other.body[i].text) return false;
    if (i > 0 && body[i].leading_space != other.body[i].leading_space) return false;
  }
  return true;
}

int Macro::param_index(std::string_view word) const {
  for (std::size_t i = 0; i < params.size(); ++i) {
    if (params[i] == word) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace safegi::detail
