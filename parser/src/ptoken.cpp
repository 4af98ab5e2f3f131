#include "ptoken.hpp"

#include <string>
#include <unordered_map>

namespace safegi::parser_detail {
namespace {

using QK = ast::QualifierKind;

struct Word {
  T kind;
  QK qual = QK::Storage;
};

const std::unordered_map<std::string, Word>& word_table() {
  static const std::unordered_map<std::string, Word> table = [] {
    std::unordered_map<std::string, Word> w;
    w.emplace("true", Word{T::True});
    w.emplace("false", Word{T::False});
    w.emplace("struct", Word{T::Struct});
    w.emplace("if", Word{T::If});
    w.emplace("else", Word{T::Else});
    w.emplace("switch", Word{T::Switch});
    w.emplace("case", Word{T::Case});
    w.emplace("default", Word{T::Default});
    w.emplace("while", Word{T::While});
    w.emplace("do", Word{T::Do});
    w.emplace("for", Word{T::For});
    w.emplace("break", Word{T::Break});
    w.emplace("continue", Word{T::Continue});
    w.emplace("discard", Word{T::Discard});
    w.emplace("return", Word{T::Return});
    w.emplace("precision", Word{T::Precision});
    w.emplace("layout", Word{T::Layout});
    w.emplace("subroutine", Word{T::Subroutine});
    w.emplace("template", Word{T::Template});
    for (const char* s : {"const", "in", "out", "inout", "attribute", "varying", "uniform", "buffer",
                          "shared", "centroid", "sample", "patch"}) {
      w.emplace(s, Word{T::QualKw, QK::Storage});
    }
    // Storage classes of ray tracing and mesh shading (the lexer makes them keywords only with their extension).
    for (const char* s : {"rayPayloadEXT", "rayPayloadInEXT", "hitAttributeEXT", "callableDataEXT", "callableDataInEXT",
                          "rayPayloadNV", "rayPayloadInNV", "hitAttributeNV", "hitObjectAttributeNV", "callableDataNV",
                          "callableDataInNV", "taskPayloadSharedEXT", "perprimitiveEXT",
                          "perprimitiveNV", "perviewNV", "taskNV"}) {
      w.emplace(s, Word{T::QualKw, QK::Storage});
    }
    for (const char* s : {"highp", "mediump", "lowp"}) w.emplace(s, Word{T::QualKw, QK::Precision});
    for (const char* s : {"smooth", "flat", "noperspective", "pervertexEXT", "pervertexNV"})
      w.emplace(s, Word{T::QualKw, QK::Interpolation});
    w.emplace("invariant", Word{T::QualKw, QK::Invariant});
    w.emplace("precise", Word{T::QualKw, QK::Precise});
    for (const char* s : {"coherent", "volatile", "restrict", "readonly", "writeonly", "devicecoherent",
                          "queuefamilycoherent", "workgroupcoherent", "subgroupcoherent", "shadercallcoherent", "nonprivate"}) {
      w.emplace(s, Word{T::QualKw, QK::Memory});
    }
    return w;
  }();
  return table;
}

T punctuation(std::string_view s) {
  static const std::unordered_map<std::string_view, T> table = {
      {"(", T::LParen},      {")", T::RParen},        {"[", T::LBracket},     {"]", T::RBracket},
      {"{", T::LBrace},      {"}", T::RBrace},        {".", T::Dot},          {",", T::Comma},
      {":", T::Colon},       {";", T::Semicolon},     {"?", T::Question},     {"+", T::Plus},
      {"-", T::Minus},       {"*", T::Star},          {"/", T::Slash},        {"%", T::Percent},
      {"&", T::Amp},         {"|", T::Pipe},          {"^", T::Caret},        {"~", T::Tilde},
      {"!", T::Bang},        {"<", T::Lt},            {">", T::Gt},           {"<=", T::Le},
      {">=", T::Ge},         {"==", T::EqEq},         {"!=", T::Ne},          {"&&", T::AmpAmp},
      {"||", T::PipePipe},   {"^^", T::CaretCaret},   {"<<", T::Shl},         {"++", T::PlusPlus},
      {"--", T::MinusMinus}, {"=", T::Assign},        {"+=", T::PlusAssign},  {"-=", T::MinusAssign},
      {"*=", T::StarAssign}, {"/=", T::SlashAssign},  {"%=", T::PercentAssign}, {"<<=", T::ShlAssign},
      {">>=", T::ShrAssign}, {"&=", T::AmpAssign},    {"|=", T::PipeAssign},  {"^=", T::CaretAssign},
  };
  auto it = table.find(s);
  return it == table.end() ? T::Unknown : it->second;
}

bool is_ident_start(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

SourceRange sub_range(SourceRange r, std::uint32_t begin, std::uint32_t end) {
  SourceRange out = r;
  out.begin.offset = r.begin.offset + begin;
  out.begin.column = r.begin.column + begin;
  out.end = r.begin;
  out.end.offset = r.begin.offset + end;
  out.end.column = r.begin.column + end;
  // A token produced by a macro expansion may not span `end - begin` bytes of
  // its range; never hand out a range past the original one.
  if (r.end.offset < out.end.offset) return r;
  return out;
}

struct KindVerdict {
  bool ready = false;
  T kind = T::Unknown;
  QK qual = QK::Storage;
  std::string_view spelling;
};

PToken classify_keyword(std::string_view text, SourceRange range, TokenKind kind);

// What append_lexer_token gives a keyword or punctuator of each kind spelled as the kind is.
const std::vector<KindVerdict>& classified_by_kind() {
  static const std::vector<KindVerdict> table = [] {
    std::vector<KindVerdict> out(kTokenKindCount);
    for (std::size_t i = 0; i < kTokenKindCount; ++i) {
      const auto kind = static_cast<TokenKind>(i);
      if (!is_keyword(kind) && !is_punctuator(kind)) continue;
      const std::string_view spelling = token_kind_spelling(kind);
      if (spelling.empty() || spelling == ">>" || spelling == ">>=") continue;
      const PToken t = is_keyword(kind) ? classify_keyword(spelling, {}, kind) : classify(spelling, {});
      out[i] = KindVerdict{true, t.kind, t.qual, spelling};
    }
    return out;
  }();
  return table;
}

}  // namespace

PToken classify(std::string_view text, SourceRange range) {
  PToken t;
  t.text = text;
  t.range = range;
  if (text.empty()) {
    t.kind = T::Eof;
  } else if (is_ident_start(text[0])) {  // keywords; type keywords are classified by the caller
    const auto& table = word_table();
    auto it = table.find(std::string(text));
    if (it == table.end()) {
      t.kind = T::Ident;
    } else {
      t.kind = it->second.kind;
      t.qual = it->second.qual;
    }
  } else {
    t.kind = punctuation(text);
  }
  return t;
}

namespace {

PToken classify_keyword(std::string_view text, SourceRange range, TokenKind kind) {
  PToken t = classify(text, range);
  if (t.kind == T::Ident) {  // a keyword this parser has no special rule for
    KeywordCategory category = keyword_category(kind);
    if (category == KeywordCategory::type) t.kind = T::TypeKw;
    if (category == KeywordCategory::qualifier) {
      t.kind = T::QualKw;
      t.qual = ast::QualifierKind::Memory;
    }
  }
  return t;
}

}  // namespace

void append_lexer_token(std::vector<PToken>& out, const Token& token) {
  std::string_view text = token.text;
  SourceRange range = token.range;
  PToken t;
  t.text = text;
  t.range = range;
  switch (token.kind) {
    case TokenKind::eof: t.kind = T::Eof; out.push_back(t); return;
    case TokenKind::identifier: t.kind = T::Ident; out.push_back(t); return;
    case TokenKind::int_literal:
    case TokenKind::int64_literal:
    case TokenKind::int16_literal: t.kind = T::IntLit; out.push_back(t); return;
    case TokenKind::uint_literal:
    case TokenKind::uint64_literal:
    case TokenKind::uint16_literal: t.kind = T::UintLit; out.push_back(t); return;
    case TokenKind::float_literal:
    case TokenKind::float16_literal: t.kind = T::FloatLit; out.push_back(t); return;
    case TokenKind::double_literal: t.kind = T::DoubleLit; out.push_back(t); return;
    case TokenKind::string_literal: t.kind = T::StringLit; out.push_back(t); return;
    default: break;
  }
  // Keywords and punctuators (but `>>` and `>>=`, which split) classify by their kind: the
  // verdict on their spelling, looked up once per kind instead of hashed per token.
  const auto& by_kind = classified_by_kind();
  if (const KindVerdict& v = by_kind[static_cast<std::size_t>(token.kind)]; v.ready && text == v.spelling) {
    t.kind = v.kind;
    t.qual = v.qual;
    out.push_back(t);
    return;
  }
  if (is_keyword(token.kind)) {
    out.push_back(classify_keyword(text, range, token.kind));
    return;
  }
  if (!is_punctuator(token.kind)) {  // reserved words, invalid bytes, strings
    t.kind = T::Unknown;
    t.reserved = token.kind == TokenKind::reserved_word;
    out.push_back(t);
    return;
  }
  if (text == ">>" || text == ">>=") {
    PToken first = classify(text.substr(0, 1), sub_range(range, 0, 1));
    first.glued = true;
    out.push_back(first);
    out.push_back(classify(text.substr(1), sub_range(range, 1, static_cast<std::uint32_t>(text.size()))));
    return;
  }
  out.push_back(classify(text, range));
}

std::string describe(const PToken& token) {
  if (token.kind == T::Eof) return "end of file";
  if (token.glued) return "'>>'";
  return "'" + std::string(token.text) + "'";
}

}  // namespace safegi::parser_detail
