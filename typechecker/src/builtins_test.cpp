#include "builtins.hpp"

#include <gtest/gtest.h>

namespace safegi {
namespace {

TEST(Builtins, EverySignatureParsesWithThePrelude) {
  const DimensionRegistry prelude = DimensionRegistry::rendering_prelude();
  BuiltinLibrary library(prelude);  // throws std::logic_error on a malformed entry
  ASSERT_NE(library.find("sqrt"), nullptr);
  const Signature& sqrt = library.find("sqrt")->front();
  EXPECT_EQ(sqrt.params.size(), 1u);
  EXPECT_EQ(sqrt.dim_params, std::vector<std::string>{"D"});
  EXPECT_EQ(sqrt.params[0].type.dim.state, DimSlot::State::generic);
  EXPECT_EQ(sqrt.params[0].type.dim.term.variables[0].second, 2);
  EXPECT_EQ(library.find("nonexistent"), nullptr);
}

TEST(Builtins, ArgumentRulesNameBuiltinsAndKeepTheirFamilies) {
  const DimensionRegistry prelude = DimensionRegistry::rendering_prelude();
  BuiltinLibrary library(prelude);
  for (const char* name : {"dot", "reflect", "refract", "faceforward"}) {
    EXPECT_NE(library.find(name), nullptr) << name;
    EXPECT_TRUE(builtin_argument_rule(name, ArgumentRule::unit_length)) << name;
    EXPECT_TRUE(builtin_argument_rule(name, ArgumentRule::no_angle_triples)) << name;
    EXPECT_TRUE(builtin_argument_rule(name, ArgumentRule::divided_only)) << name;
  }
  for (const char* name : {"normalize", "length", "dFdx", "dFdyCoarse", "fwidthFine"}) {
    EXPECT_NE(library.find(name), nullptr) << name;
    EXPECT_TRUE(builtin_argument_rule(name, ArgumentRule::divided_only)) << name;
  }
  EXPECT_FALSE(builtin_argument_rule("length", ArgumentRule::unit_length));  // length(vN) takes it as it is
  EXPECT_FALSE(builtin_argument_rule("mix", ArgumentRule::divided_only));
}

TEST(Builtins, WithoutThePreludeNamedDimensionsAreUnknown) {
  BuiltinLibrary library{DimensionRegistry{}};
  const Signature& sin = library.find("sin")->front();
  EXPECT_EQ(sin.params[0].type.dim.state, DimSlot::State::unknown);
  EXPECT_EQ(sin.result.type.dim.state, DimSlot::State::known);  // `1` needs no declaration
}

TEST(Builtins, ShapeMatchingPrefersGeometricOverloads) {
  const DimensionRegistry prelude = [] {
    DimensionRegistry r = DimensionRegistry::rendering_prelude();
    r.add_space("world");
    return r;
  }();
  BuiltinLibrary library(prelude);
  Type normal = Type::vector_of(Scalar::float_, 3);
  normal.geometry = Geometry::normal;
  Type direction = normal;
  direction.geometry = Geometry::direction;
  auto m = match_shapes(*library.find("dot"), {{normal, false}, {direction, false}});
  ASSERT_TRUE(m);
  EXPECT_EQ(m->signature->text, "normal<S>, direction<S> -> float<proj>");
  auto plain = match_shapes(*library.find("dot"), {{Type::vector_of(Scalar::float_, 2), false}, {Type::vector_of(Scalar::float_, 2), false}});
  ASSERT_TRUE(plain);
  EXPECT_EQ(plain->signature->text, "genF<D>, genF<E> -> float<D*E>");
  EXPECT_EQ(plain->n, 2);
  EXPECT_FALSE(match_shapes(*library.find("dot"), {{Type::vector_of(Scalar::float_, 2), false}, {Type::vector_of(Scalar::float_, 3), false}}));
  auto conv = match_shapes(*library.find("max"), {{Type::scalar_of(Scalar::float_), false}, {Type::scalar_of(Scalar::int_), false}});
  ASSERT_TRUE(conv);
  EXPECT_EQ(conv->cost, 1);
}

TEST(Builtins, MatrixSizeClasses) {
  BuiltinLibrary library{DimensionRegistry{}};
  auto m = match_shapes(*library.find("transpose"), {{Type::matrix_of(Scalar::float_, 2, 3), false}});
  ASSERT_TRUE(m);
  Type t = instantiate_shape(m->signature->result, *m);
  EXPECT_EQ(glsl_name(t), "mat3x2");
  auto outer = match_shapes(*library.find("outerProduct"), {{Type::vector_of(Scalar::float_, 3), false}, {Type::vector_of(Scalar::float_, 2), false}});
  ASSERT_TRUE(outer);
  EXPECT_EQ(glsl_name(instantiate_shape(outer->signature->result, *outer)), "mat2x3");
  EXPECT_FALSE(match_shapes(*library.find("determinant"), {{Type::matrix_of(Scalar::float_, 2, 3), false}}));
}

}  // namespace
}  // namespace safegi
