#include <safegi/lexer/token.hpp>
#include <safegi/lexer/extensions.hpp>

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace safegi {
namespace {

struct KeywordRow {
  TokenKind kind;
  std::string_view spelling;
};
const std::vector<KeywordRow> kKeywords = {
#define SAFEGI_KEYWORD(name, spelling, category, desktop_since, es_since, group, es_reserved_from) \
  {TokenKind::name, spelling},
#include <safegi/lexer/token_kinds.def>
};
const std::vector<std::string_view> kReservedWords = {
#define SAFEGI_RESERVED_WORD(spelling, desktop_since, es_since) spelling,
#include <safegi/lexer/token_kinds.def>
};

KeywordContext context(int version, bool es = false) {
  KeywordContext c;
  c.version = version;
  c.es = es;
  return c;
}

TEST(Token, EveryKeywordIsAKeywordWhenEverythingIsEnabled) {
  ASSERT_GT(kKeywords.size(), 280u);
  KeywordContext all = KeywordContext::everything();
  all.enable(ExtensionGroup::vulkan);
  for (const KeywordRow& k : kKeywords) {
    EXPECT_EQ(classify_word(k.spelling, all), k.kind) << k.spelling;
    EXPECT_TRUE(is_keyword(k.kind)) << k.spelling;
    EXPECT_EQ(token_kind_spelling(k.kind), k.spelling);
    EXPECT_EQ(token_kind_description(k.kind), "'" + std::string(k.spelling) + "'");
  }
}

TEST(Token, ReservedWordsAreFlagged) {
  for (std::string_view word : kReservedWords) {
    // `packed` is given back as a name from 3.30 (PackedIsReservedOnlyBeforeGlsl330): reserved at 1.50.
    const KeywordContext where = word == "packed" ? context(150) : KeywordContext::everything();
    EXPECT_EQ(classify_word(word, where), TokenKind::reserved_word) << word;
  }
  EXPECT_EQ(classify_word("class", context(110)), TokenKind::reserved_word);
  EXPECT_EQ(classify_word("goto", context(300, true)), TokenKind::reserved_word);
  EXPECT_EQ(classify_word("resource", context(330)), TokenKind::identifier);
  EXPECT_EQ(classify_word("resource", context(420)), TokenKind::reserved_word);
}

TEST(Token, VulkanTypesNeedVulkan) {
  EXPECT_EQ(classify_word("sampler", KeywordContext::everything()), TokenKind::identifier);
  EXPECT_EQ(classify_word("texture2D", KeywordContext::everything()), TokenKind::identifier);
  EXPECT_EQ(classify_word("image2D", KeywordContext::everything()), TokenKind::kw_image2D);
  EXPECT_EQ(classify_word("int64_t", KeywordContext::everything()), TokenKind::kw_int64_t);
}

TEST(Token, TemplateIsAKeywordForGenericFunctions) {
  EXPECT_EQ(classify_word("template", context(110)), TokenKind::kw_template);
  EXPECT_EQ(classify_word("template", context(300, true)), TokenKind::kw_template);
}

TEST(Token, AnnotationWordsAreIdentifiers) {
  for (std::string_view word : {"dimension", "unit", "space", "point", "vector", "direction", "normal", "spectrum",
                                "map", "projmap", "hpoint", "length", "texture"}) {
    EXPECT_EQ(classify_word(word, KeywordContext::everything()), TokenKind::identifier) << word;
  }
}

TEST(Token, KeywordsDependOnVersionAndProfile) {
  EXPECT_EQ(classify_word("sample", context(330)), TokenKind::identifier);
  EXPECT_EQ(classify_word("sample", context(400)), TokenKind::kw_sample);
  EXPECT_EQ(classify_word("sample", context(310, true)), TokenKind::reserved_word);
  EXPECT_EQ(classify_word("sample", context(320, true)), TokenKind::kw_sample);
  EXPECT_EQ(classify_word("uint", context(120)), TokenKind::identifier);
  EXPECT_EQ(classify_word("uint", context(130)), TokenKind::kw_uint);
  EXPECT_EQ(classify_word("mat2x3", context(110)), TokenKind::identifier);
  EXPECT_EQ(classify_word("mat2x3", context(120)), TokenKind::kw_mat2x3);
  EXPECT_EQ(classify_word("double", context(100, true)), TokenKind::identifier);
  EXPECT_EQ(classify_word("double", context(300, true)), TokenKind::reserved_word);
  EXPECT_EQ(classify_word("double", context(400)), TokenKind::kw_double);
  EXPECT_EQ(classify_word("highp", context(120)), TokenKind::identifier);
  EXPECT_EQ(classify_word("highp", context(100, true)), TokenKind::kw_highp);
  EXPECT_EQ(classify_word("buffer", context(330)), TokenKind::identifier);
  EXPECT_EQ(classify_word("buffer", context(430)), TokenKind::kw_buffer);
  EXPECT_EQ(classify_word("texture2D", context(460)), TokenKind::identifier);  // a function before Vulkan
  EXPECT_EQ(classify_word("int64_t", context(460)), TokenKind::identifier);
}

TEST(Token, ExtensionsEnableKeywords) {
  KeywordContext c = context(150);
  EXPECT_EQ(classify_word("patch", c), TokenKind::identifier);
  c.extension_groups |= extension_groups_enabled_by("GL_ARB_tessellation_shader");
  EXPECT_EQ(classify_word("patch", c), TokenKind::kw_patch);
  c.extension_groups |= extension_groups_enabled_by("GL_EXT_shader_explicit_arithmetic_types_int64");
  EXPECT_EQ(classify_word("u64vec3", c), TokenKind::kw_u64vec3);
  c.extension_groups |= extension_groups_enabled_by("GL_KHR_vulkan_glsl");
  EXPECT_EQ(classify_word("subpassInput", c), TokenKind::kw_subpassInput);
  EXPECT_EQ(extension_groups_enabled_by("GL_EXT_unknown"), 0u);
}

TEST(Token, RayTracingAndMeshQualifiersAreKeywordsOnlyWithTheirExtensions) {
  KeywordContext c = context(460);
  for (std::string_view word : {"rayPayloadEXT", "hitAttributeEXT", "taskPayloadSharedEXT", "nonuniformEXT", "pervertexEXT"})
    EXPECT_EQ(classify_word(word, c), TokenKind::identifier) << word;
  c.extension_groups |= extension_groups_enabled_by("GL_EXT_ray_tracing") | extension_groups_enabled_by("GL_EXT_mesh_shader") |
                        extension_groups_enabled_by("GL_EXT_nonuniform_qualifier") |
                        extension_groups_enabled_by("GL_EXT_fragment_shader_barycentric");
  const std::pair<std::string_view, TokenKind> keywords[] = {
      {"rayPayloadEXT", TokenKind::kw_rayPayloadEXT},   {"callableDataInEXT", TokenKind::kw_callableDataInEXT},
      {"taskPayloadSharedEXT", TokenKind::kw_taskPayloadSharedEXT}, {"perprimitiveEXT", TokenKind::kw_perprimitiveEXT},
      {"nonuniformEXT", TokenKind::kw_nonuniformEXT},   {"pervertexEXT", TokenKind::kw_pervertexEXT}};
  for (const auto& [word, kind] : keywords) EXPECT_EQ(classify_word(word, c), kind) << word;
}

// glslang: `packed` is reserved before GLSL 3.30 only.
TEST(Token, PackedIsReservedOnlyBeforeGlsl330) {
  EXPECT_EQ(classify_word("packed", context(150)), TokenKind::reserved_word);
  EXPECT_EQ(classify_word("packed", context(330)), TokenKind::identifier);
  EXPECT_EQ(classify_word("packed", context(460)), TokenKind::identifier);
}

TEST(Token, ExtensionTableIsSortedAndNamesTheDefaultMacros) {
  auto known = known_extensions();
  for (std::size_t i = 1; i < known.size(); ++i) EXPECT_LT(known[i - 1].name, known[i].name);
  EXPECT_EQ(default_extension_macros().size(), known.size());
  EXPECT_NE(find_extension("GL_ARB_shader_subroutine"), nullptr);
  // Cooperative matrices are syntax the parser does not have: not listed, so `#ifdef` says so.
  EXPECT_EQ(find_extension("GL_NV_cooperative_matrix"), nullptr);
  // [[unroll]] and `= {}` are parsed (issue 46).
  EXPECT_NE(find_extension("GL_EXT_control_flow_attributes"), nullptr);
  EXPECT_NE(find_extension("GL_EXT_null_initializer"), nullptr);
  EXPECT_NE(find_extension("GL_NV_ray_tracing"), nullptr);
  // Vulkan GLSL enables its types but is no driver extension macro.
  EXPECT_NE(extension_groups_enabled_by("GL_KHR_vulkan_glsl"), 0u);
  for (const std::string& name : default_extension_macros()) EXPECT_NE(name, "GL_KHR_vulkan_glsl");
}

TEST(Token, ExtensionsEnableKeywordsOfOlderVersions) {
  KeywordContext c = context(130);
  for (std::string_view word : {"subroutine", "coherent", "readonly", "buffer", "layout"}) {
    EXPECT_EQ(classify_word(word, c), TokenKind::identifier) << word;
  }
  c.extension_groups |= extension_groups_enabled_by("GL_ARB_shader_subroutine") |
                        extension_groups_enabled_by("GL_ARB_shader_storage_buffer_object") |
                        extension_groups_enabled_by("GL_ARB_fragment_coord_conventions");
  EXPECT_EQ(classify_word("subroutine", c), TokenKind::kw_subroutine);
  EXPECT_EQ(classify_word("coherent", c), TokenKind::kw_coherent);
  EXPECT_EQ(classify_word("readonly", c), TokenKind::kw_readonly);
  EXPECT_EQ(classify_word("buffer", c), TokenKind::kw_buffer);
  EXPECT_EQ(classify_word("layout", c), TokenKind::kw_layout);
  EXPECT_EQ(classify_word("image2D", c), TokenKind::reserved_word);  // storage buffers bring no images
  KeywordContext old = context(120);
  old.extension_groups |= extension_groups_enabled_by("GL_EXT_gpu_shader4");
  EXPECT_EQ(classify_word("flat", old), TokenKind::kw_flat);
  EXPECT_EQ(classify_word("noperspective", old), TokenKind::kw_noperspective);
}

TEST(Token, LaterKeywordsAreReservedInOlderDesktopVersions) {
  EXPECT_EQ(classify_word("double", context(110)), TokenKind::reserved_word);
  EXPECT_EQ(classify_word("double", context(400)), TokenKind::kw_double);
  EXPECT_EQ(classify_word("image2D", context(120)), TokenKind::identifier);
  EXPECT_EQ(classify_word("image2D", context(130)), TokenKind::reserved_word);
  EXPECT_EQ(classify_word("samplerBuffer", context(130)), TokenKind::reserved_word);
  EXPECT_EQ(classify_word("samplerBuffer", context(140)), TokenKind::kw_samplerBuffer);
  EXPECT_EQ(classify_word("image2D", context(300, true)), TokenKind::identifier);  // desktop lists only
  KeywordContext fp64 = context(150);
  fp64.extension_groups |= extension_groups_enabled_by("GL_ARB_gpu_shader_fp64");
  EXPECT_EQ(classify_word("dvec3", fp64), TokenKind::kw_dvec3);
}

TEST(Token, FeatureGates) {
  LanguageLevel level;
  level.version = 330;
  EXPECT_FALSE(level.allows(LanguageFeature::double_literals));
  EXPECT_FALSE(level.allows(LanguageFeature::arrays_of_arrays));
  level.extensions = {"GL_ARB_gpu_shader_fp64", "GL_ARB_arrays_of_arrays"};
  EXPECT_TRUE(level.allows(LanguageFeature::double_literals));
  EXPECT_TRUE(level.allows(LanguageFeature::arrays_of_arrays));
  LanguageLevel es{310, true, {}};
  EXPECT_TRUE(es.allows(LanguageFeature::arrays_of_arrays));
  EXPECT_FALSE(es.allows(LanguageFeature::double_literals));
  EXPECT_TRUE(LanguageLevel::everything().allows(LanguageFeature::double_literals));
  EXPECT_EQ(feature_requirement(LanguageFeature::arrays_of_arrays, false),
            "arrays of arrays require #version 430 or GL_ARB_arrays_of_arrays");
  EXPECT_EQ(feature_requirement(LanguageFeature::arrays_of_arrays, true),
            "arrays of arrays require #version 310 es or GL_ARB_arrays_of_arrays");
  EXPECT_EQ(feature_requirement(LanguageFeature::double_literals, true),
            "double-precision literals ('lf' suffix) are not available in GLSL ES (without GL_ARB_gpu_shader_fp64)");
  EXPECT_EQ(feature_requirement(LanguageFeature::global_in_out, false),
            "'in' and 'out' on global variables require #version 130");
}

TEST(Token, KindNamesAndCategories) {
  EXPECT_EQ(token_kind_name(TokenKind::l_paren), "l_paren");
  EXPECT_EQ(token_kind_name(TokenKind::kw_sampler2DShadow), "kw_sampler2DShadow");
  EXPECT_EQ(token_kind_description(TokenKind::identifier), "identifier");
  EXPECT_EQ(token_kind_description(TokenKind::greater_greater_equal), "'>>='");
  EXPECT_EQ(token_kind_spelling(TokenKind::caret_caret), "^^");
  EXPECT_EQ(keyword_category(TokenKind::kw_vec3), KeywordCategory::type);
  EXPECT_EQ(keyword_category(TokenKind::kw_flat), KeywordCategory::qualifier);
  EXPECT_EQ(keyword_category(TokenKind::kw_while), KeywordCategory::statement);
  EXPECT_EQ(keyword_category(TokenKind::kw_true), KeywordCategory::literal);
  EXPECT_EQ(keyword_category(TokenKind::plus), KeywordCategory::none);
  EXPECT_TRUE(is_type_keyword(TokenKind::kw_atomic_uint));
  EXPECT_TRUE(is_punctuator(TokenKind::hash_hash));
  EXPECT_FALSE(is_punctuator(TokenKind::kw_float));
  EXPECT_TRUE(is_literal(TokenKind::kw_false));
  EXPECT_TRUE(is_numeric_literal(TokenKind::float16_literal));
  EXPECT_FALSE(is_numeric_literal(TokenKind::string_literal));
}

Token make(TokenKind kind, std::string_view text, std::uint32_t offset) {
  Token t;
  t.kind = kind;
  t.text = text;
  t.range.begin = {1, offset, 1, offset + 1};
  t.range.end = {1, offset + static_cast<std::uint32_t>(text.size()), 1,
                 offset + 1 + static_cast<std::uint32_t>(text.size())};
  return t;
}

TEST(Token, SplitLeadingGreater) {
  auto split = split_leading_greater(make(TokenKind::greater_greater, ">>", 10));
  ASSERT_TRUE(split);
  EXPECT_EQ(split->first.kind, TokenKind::greater);
  EXPECT_EQ(split->first.text, ">");
  EXPECT_EQ(split->first.range.end.offset, 11u);
  EXPECT_EQ(split->second.kind, TokenKind::greater);
  EXPECT_EQ(split->second.range.begin.offset, 11u);
  EXPECT_EQ(split->second.range.begin.column, 12u);
  EXPECT_EQ(split->second.range.end.offset, 12u);
  EXPECT_EQ(split_leading_greater(make(TokenKind::greater_greater_equal, ">>=", 0))->second.kind,
            TokenKind::greater_equal);
  EXPECT_EQ(split_leading_greater(make(TokenKind::greater_equal, ">=", 0))->second.kind, TokenKind::equal);
  EXPECT_FALSE(split_leading_greater(make(TokenKind::greater, ">", 0)));
}

TEST(Token, LiteralValues) {
  EXPECT_EQ(integer_literal_value("42"), 42u);
  EXPECT_EQ(integer_literal_value("42u"), 42u);
  EXPECT_EQ(integer_literal_value("0x1F"), 31u);
  EXPECT_EQ(integer_literal_value("0XffFFffFF"), 0xFFFFFFFFu);
  EXPECT_EQ(integer_literal_value("017"), 15u);
  EXPECT_EQ(integer_literal_value("0"), 0u);
  EXPECT_EQ(integer_literal_value("18446744073709551615ul"), UINT64_MAX);
  EXPECT_FALSE(integer_literal_value("18446744073709551616"));
  EXPECT_FALSE(integer_literal_value("09"));
  EXPECT_DOUBLE_EQ(float_literal_value("1.5"), 1.5);
  EXPECT_DOUBLE_EQ(float_literal_value(".5f"), 0.5);
  EXPECT_DOUBLE_EQ(float_literal_value("5."), 5.0);
  EXPECT_DOUBLE_EQ(float_literal_value("2e3lf"), 2000.0);
  EXPECT_DOUBLE_EQ(float_literal_value("1.5E-2"), 0.015);
}

}  // namespace
}  // namespace safegi
