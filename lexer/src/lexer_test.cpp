#include <safegi/lexer/lexer.hpp>

#include <gtest/gtest.h>

#include <safegi/diagnostics/render.hpp>

#include <string>
#include <vector>

namespace safegi {
namespace {

class LexerTest : public ::testing::Test {
 protected:
  std::vector<Token> lex(std::string source, LexerOptions options = {}) {
    file = sources.add_file("t.glsl", std::move(source));
    return tokenize(sources, file, diagnostics, options);
  }
  std::vector<TokenKind> kinds(std::string source) {
    std::vector<TokenKind> result;
    for (const Token& t : lex(std::move(source))) result.push_back(t.kind);
    return result;
  }
  std::string errors() const { return render_text(diagnostics.diagnostics(), sources); }

  struct Row {
    const char* text;
    TokenKind kind;
  };
  // Each text lexes to exactly one token of the given kind, spelled as written.
  void expect_single_tokens(std::initializer_list<Row> rows) {
    for (Row r : rows) {
      auto tokens = lex(r.text);
      ASSERT_EQ(tokens.size(), 2u) << r.text;
      EXPECT_EQ(tokens[0].kind, r.kind) << r.text;
      EXPECT_EQ(tokens[0].text, r.text);
    }
  }

  SourceManager sources;
  DiagnosticEngine diagnostics;
  FileId file = kNoFile;
};

using K = TokenKind;

TEST_F(LexerTest, EveryPunctuator) {
  struct Row {
    TokenKind kind;
    std::string_view spelling;
  };
  const std::vector<Row> punctuators = {
#define SAFEGI_PUNCTUATOR(name, spelling) {TokenKind::name, spelling},
#include <safegi/lexer/token_kinds.def>
  };
  ASSERT_EQ(punctuators.size(), 47u);
  for (const Row& p : punctuators) {
    auto tokens = lex(std::string(p.spelling));
    ASSERT_EQ(tokens.size(), 2u) << p.spelling;
    EXPECT_EQ(tokens[0].kind, p.kind) << p.spelling;
    EXPECT_EQ(tokens[0].text, p.spelling);
  }
  EXPECT_EQ(errors(), "");
}

TEST_F(LexerTest, LongestMatch) {
  EXPECT_EQ(kinds("a+++b"), (std::vector<K>{K::identifier, K::plus_plus, K::plus, K::identifier, K::eof}));
  EXPECT_EQ(kinds(">>=>>>"), (std::vector<K>{K::greater_greater_equal, K::greater_greater, K::greater, K::eof}));
  EXPECT_EQ(kinds("<<=<<<"), (std::vector<K>{K::less_less_equal, K::less_less, K::less, K::eof}));
  EXPECT_EQ(kinds("^^^=&&&=|||="),
            (std::vector<K>{K::caret_caret, K::caret_equal, K::amp_amp, K::amp_equal, K::pipe_pipe, K::pipe_equal,
                            K::eof}));
  EXPECT_EQ(kinds("a.b"), (std::vector<K>{K::identifier, K::dot, K::identifier, K::eof}));
  EXPECT_EQ(kinds("v.x.5"), (std::vector<K>{K::identifier, K::dot, K::identifier, K::float_literal, K::eof}));
}

TEST_F(LexerTest, IntegerLiterals) {
  expect_single_tokens({Row{"0", K::int_literal}, Row{"123", K::int_literal}, Row{"0x1aF", K::int_literal},
                        Row{"0XFF", K::int_literal}, Row{"0777", K::int_literal}, Row{"4294967295", K::int_literal},
                        Row{"0xFFFFFFFF", K::int_literal}, Row{"7u", K::uint_literal}, Row{"7U", K::uint_literal},
                        Row{"0x10u", K::uint_literal}, Row{"017U", K::uint_literal}, Row{"5l", K::int64_literal},
                        Row{"5L", K::int64_literal}, Row{"5ul", K::uint64_literal}, Row{"5UL", K::uint64_literal},
                        Row{"18446744073709551615UL", K::uint64_literal}, Row{"3s", K::int16_literal},
                        Row{"3us", K::uint16_literal}, Row{"65535US", K::uint16_literal}});
  EXPECT_EQ(errors(), "");
}

TEST_F(LexerTest, FloatLiterals) {
  expect_single_tokens({Row{"1.0", K::float_literal}, Row{".5", K::float_literal}, Row{"5.", K::float_literal},
                        Row{"1e10", K::float_literal}, Row{"1E-3", K::float_literal}, Row{"2.5e+7", K::float_literal},
                        Row{".5e2", K::float_literal}, Row{"1.0f", K::float_literal}, Row{"1.F", K::float_literal},
                        Row{"1e3f", K::float_literal}, Row{"1.0lf", K::double_literal}, Row{"2.LF", K::double_literal},
                        Row{"1e-2lf", K::double_literal}, Row{"1.5hf", K::float16_literal}, Row{"0.0", K::float_literal},
                        Row{"09.5", K::float_literal}, Row{"00.5", K::float_literal}, Row{"1.0lF", K::double_literal},
                        Row{"1.0Lf", K::double_literal}, Row{"2.0hF", K::float16_literal}, Row{"1e+5", K::float_literal}});
  EXPECT_EQ(errors(), "");
}

TEST_F(LexerTest, BadLiterals) {
  lex("int a = 09;\nfloat b = 1.0x;\nint c = 4294967296;\nint d = 0x;\nfloat e = 1e+;\nfloat f = 2f;\n"
      "int g = 5q;\nfloat h = 1.5e;\n");
  EXPECT_EQ(errors(),
            "t.glsl:1:9: error: invalid digit '9' in octal literal [E-LITERAL]\n"
            "int a = 09;\n"
            "        ^~\n"
            "t.glsl:2:14: error: invalid suffix 'x' on floating-point literal [E-LITERAL]\n"
            "float b = 1.0x;\n"
            "             ^\n"
            "t.glsl:3:9: error: integer literal '4294967296' does not fit in 32 bits [E-LITERAL]\n"
            "int c = 4294967296;\n"
            "        ^~~~~~~~~~\n"
            "t.glsl:4:9: error: hexadecimal literal has no digits [E-LITERAL]\n"
            "int d = 0x;\n"
            "        ^~\n"
            "t.glsl:5:11: error: exponent has no digits [E-LITERAL]\n"
            "float e = 1e+;\n"
            "          ^~~\n"
            "t.glsl:6:11: error: a floating-point literal needs a '.' or an exponent (write '2.0f') [E-LITERAL]\n"
            "float f = 2f;\n"
            "          ^~\n"
            "t.glsl:7:10: error: invalid suffix 'q' on integer literal [E-LITERAL]\n"
            "int g = 5q;\n"
            "         ^\n"
            "t.glsl:8:14: error: exponent has no digits [E-LITERAL]\n"
            "float h = 1.5e;\n"
            "             ^\n");
}

TEST_F(LexerTest, WordsAndKeywords) {
  auto tokens = lex("float x_1 = _y; dimension length; vec3 spectrum");
  EXPECT_EQ(tokens[0].kind, K::kw_float);
  EXPECT_EQ(tokens[1].kind, K::identifier);
  EXPECT_EQ(tokens[1].text, "x_1");
  EXPECT_EQ(tokens[3].text, "_y");
  EXPECT_EQ(tokens[5].kind, K::identifier);  // annotation words are identifiers
  EXPECT_EQ(tokens[8].kind, K::kw_vec3);
  EXPECT_EQ(tokens[9].kind, K::identifier);

  LexerOptions words_only;
  words_only.classify_words = false;
  EXPECT_EQ(lex("float", words_only)[0].kind, K::identifier);
}

TEST_F(LexerTest, RangesAndFlags) {
  auto tokens = lex("  a /*c*/b\n\tc//x\n d");
  ASSERT_EQ(tokens.size(), 5u);
  EXPECT_EQ(tokens[0].range, sources.range_of(file, 2, 3));
  EXPECT_TRUE(tokens[0].at_line_start);
  EXPECT_TRUE(tokens[0].leading_space);
  EXPECT_FALSE(tokens[1].at_line_start);
  EXPECT_TRUE(tokens[1].leading_space);
  EXPECT_EQ(tokens[1].range.begin.column, 10u);
  EXPECT_TRUE(tokens[2].at_line_start);
  EXPECT_EQ(tokens[2].range.begin.line, 2u);
  EXPECT_EQ(tokens[2].range.begin.column, 2u);
  EXPECT_TRUE(tokens[3].at_line_start);
  EXPECT_EQ(tokens[3].text, "d");
  EXPECT_EQ(tokens[4].kind, K::eof);
  EXPECT_EQ(tokens[4].range.begin.offset, 19u);
}

TEST_F(LexerTest, NoSpaceFlag) {
  auto tokens = lex("a(b");
  EXPECT_FALSE(tokens[1].leading_space);
  EXPECT_FALSE(tokens[2].leading_space);
}

TEST_F(LexerTest, BlockCommentSpanningLinesDoesNotStartALine) {
  auto tokens = lex("a /* x\ny */ b\nc");
  EXPECT_FALSE(tokens[1].at_line_start);
  EXPECT_TRUE(tokens[2].at_line_start);
}

TEST_F(LexerTest, LineContinuations) {
  auto tokens = lex("flo\\\nat x = 1\\\r\n.5;// comment \\\ncontinued\ny");
  ASSERT_EQ(tokens.size(), 7u);
  EXPECT_EQ(tokens[0].kind, K::kw_float);
  EXPECT_EQ(tokens[0].text, "float");
  EXPECT_EQ(tokens[0].range, sources.range_of(file, 0, 7));
  EXPECT_EQ(tokens[3].kind, K::float_literal);
  EXPECT_EQ(tokens[3].text, "1.5");
  EXPECT_EQ(tokens[5].text, "y");
  EXPECT_EQ(tokens[5].range.begin.line, 5u);
  EXPECT_EQ(errors(), "");
}

TEST_F(LexerTest, UnterminatedComment) {
  auto tokens = lex("a\n  /* never\nclosed");
  EXPECT_EQ(tokens.size(), 2u);
  EXPECT_EQ(errors(),
            "t.glsl:2:3: error: unterminated /* comment [E-UNTERMINATED-COMMENT]\n"
            "  /* never\n"
            "  ^~\n");
}

TEST_F(LexerTest, InvalidCharacters) {
  auto tokens = lex("a @ $b;\nc \\ d;\nfloat \xC3\xA9t\xC3\xA9 = 1; // caf\xC3\xA9 ok\n`\x01");
  EXPECT_EQ(tokens[1].kind, K::invalid);
  EXPECT_EQ(errors(),
            "t.glsl:1:3: error: invalid character '@' in program [E-CHARACTER]\n"
            "a @ $b;\n"
            "  ^\n"
            "t.glsl:1:5: error: invalid character '$' in program [E-CHARACTER]\n"
            "a @ $b;\n"
            "    ^\n"
            "t.glsl:2:3: error: stray '\\' in program (a line continuation must be the last character on its line) [E-CHARACTER]\n"
            "c \\ d;\n"
            "  ^\n"
            "t.glsl:3:7: error: non-ASCII character '\xC3\xA9' outside a comment [E-CHARACTER]\n"
            "float \xC3\xA9t\xC3\xA9 = 1; // caf\xC3\xA9 ok\n"
            "      ^\n"
            "t.glsl:3:10: error: non-ASCII character '\xC3\xA9' outside a comment [E-CHARACTER]\n"
            "float \xC3\xA9t\xC3\xA9 = 1; // caf\xC3\xA9 ok\n"
            "        ^\n"
            "t.glsl:4:1: error: invalid character '`' in program [E-CHARACTER]\n"
            "`\\x01\n"  // the control byte quoted as text, four columns wide
            "^\n"
            "t.glsl:4:2: error: invalid control character 0x01 in program [E-CHARACTER]\n"
            "`\\x01\n"
            " ^~~~\n");
}

TEST_F(LexerTest, StringLiterals) {
  auto tokens = lex("\"a b\" \"open\nx");
  EXPECT_EQ(tokens[0].kind, K::string_literal);
  EXPECT_EQ(tokens[0].text, "\"a b\"");
  EXPECT_EQ(tokens[1].kind, K::string_literal);
  EXPECT_EQ(tokens[2].text, "x");
  EXPECT_EQ(errors(),
            "t.glsl:1:7: error: missing terminating '\"' character [E-CHARACTER]\n"
            "\"a b\" \"open\n"
            "      ^~~~~\n");
}

TEST_F(LexerTest, ErrorsCanBeSilenced) {
  file = sources.add_file("t.glsl", "@ /* x");
  Lexer lexer(sources, file, diagnostics);
  lexer.set_report_errors(false);
  EXPECT_EQ(lexer.next().kind, K::invalid);
  EXPECT_EQ(lexer.next().kind, K::eof);
  EXPECT_EQ(diagnostics.error_count(), 1u);  // the unterminated comment only
}

TEST_F(LexerTest, RestOfLineAndHeaderName) {
  file = sources.add_file("t.glsl", "#error  some text /* c */ here  // tail\nnext\n#include <a/b.h>\n");
  Lexer lexer(sources, file, diagnostics);
  EXPECT_EQ(lexer.next().kind, K::hash);
  EXPECT_EQ(lexer.next().text, "error");
  SourceRange rest = lexer.rest_of_line();
  EXPECT_EQ(sources.text(file).substr(rest.begin.offset, rest.length()), "some text /* c */ here");
  Token next = lexer.next();
  EXPECT_EQ(next.text, "next");
  EXPECT_TRUE(next.at_line_start);
  lexer.next();
  lexer.next();
  auto header = lexer.header_name();
  ASSERT_TRUE(header);
  EXPECT_EQ(header->text, "<a/b.h>");
  EXPECT_EQ(lexer.next().kind, K::eof);
}

TEST_F(LexerTest, ByteOrderMarkIsSkipped) {
  auto tokens = lex("\xEF\xBB\xBFx");
  ASSERT_EQ(tokens.size(), 2u);
  EXPECT_EQ(tokens[0].text, "x");
  EXPECT_EQ(tokens[0].range.begin.column, 4u);
  EXPECT_EQ(errors(), "");
}

TEST_F(LexerTest, EofRepeats) {
  file = sources.add_file("t.glsl", "");
  Lexer lexer(sources, file, diagnostics);
  EXPECT_EQ(lexer.next().kind, K::eof);
  EXPECT_EQ(lexer.next().kind, K::eof);
}

}  // namespace
}  // namespace safegi
