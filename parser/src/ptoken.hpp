#pragma once
// The parser's view of a token: the lexer's token reclassified by its
// spelling into the kinds the grammar needs. Keeping this view private means
// the parser depends only on a token's text and range, and annotation words
// stay ordinary identifiers (docs/language.md, "How annotations are told apart").

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <safegi/diagnostics/source_location.hpp>
#include <safegi/lexer/token.hpp>
#include <safegi/parser/ast.hpp>

namespace safegi::parser_detail {

enum class T : std::uint8_t {
  Eof,
  Ident,
  TypeKw,      // a GLSL type keyword (float, vec3, sampler2D, ...)
  QualKw,      // a qualifier keyword other than layout / subroutine / precision-statement
  IntLit,
  UintLit,
  FloatLit,
  DoubleLit,
  StringLit,  // GL_EXT_debug_printf; the preprocessor rejects strings elsewhere
  True,
  False,
  // keywords
  Struct, If, Else, Switch, Case, Default, While, Do, For, Break, Continue, Discard, Return,
  Precision, Layout, Subroutine, Template,
  // punctuation
  LParen, RParen, LBracket, RBracket, LBrace, RBrace, Dot, Comma, Colon, Semicolon, Question,
  Plus, Minus, Star, Slash, Percent, Amp, Pipe, Caret, Tilde, Bang,
  Lt, Gt, Le, Ge, EqEq, Ne, AmpAmp, PipePipe, CaretCaret, Shl, PlusPlus, MinusMinus,
  Assign, PlusAssign, MinusAssign, StarAssign, SlashAssign, PercentAssign,
  ShlAssign, ShrAssign, AmpAssign, PipeAssign, CaretAssign,
  Unknown,  // anything else the lexer let through (reported when reached)
};

struct PToken {
  T kind = T::Eof;
  ast::QualifierKind qual = ast::QualifierKind::Storage;  // for QualKw
  // `>>` and `>>=` arrive split into `>` `>` and `>` `>=` so that annotations
  // can close one level at a time; `glued` marks the first half, which the
  // expression parser joins back into a shift.
  bool glued = false;
  // A word GLSL reserves (`common`, `filter`, `input`; T::Unknown): no GLSL use, but it may
  // name a space, dimension or unit, whose declarations and uses are erased from the output.
  bool reserved = false;
  std::string_view text;
  SourceRange range;
};

// Classifies a keyword or punctuator by its spelling; `>>` and `>>=` must
// already be split. Words not special to the parser come back as Ident.
PToken classify(std::string_view text, SourceRange range);

// Appends the token(s) for one lexer token, splitting `>>` / `>>=`. Words
// keep the lexer's version-aware verdict: a word the lexer calls an
// identifier (`sample` in #version 330) stays one.
void append_lexer_token(std::vector<PToken>& out, const Token& token);

std::string describe(const PToken& token);  // "'x'" or "end of file", for messages

}  // namespace safegi::parser_detail
