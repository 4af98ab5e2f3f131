#include "safegi/dimension_algebra/unifier.hpp"

#include <gtest/gtest.h>

namespace safegi {
namespace {

class Unify : public ::testing::Test {
 protected:
  DimensionRegistry r = DimensionRegistry::rendering_prelude();
  DimensionUnifier u;
  Dimension dim(std::initializer_list<std::pair<std::string_view, std::int32_t>> terms) { return *r.make(terms); }
  DimTerm term(std::initializer_list<std::pair<std::string_view, std::int32_t>> terms,
               std::vector<std::pair<DimVarId, std::int32_t>> vars = {}) {
    return {dim(terms), std::move(vars)};
  }
};

TEST_F(Unify, SqrtOfSquareGivesTheDimension) {
  // sqrt: float<D^2> -> float<D>, called with area
  DimVarId d = u.add_variable("D");
  u.add_equation(DimTerm::variable(d, 2), DimTerm::of(dim({{"area", 1}})));
  UnifyResult res = u.solve();
  ASSERT_TRUE(res.ok());
  EXPECT_EQ(res.variables[d].value, dim({{"length", 1}}));
  EXPECT_EQ(u.explain(res, r), "D = length");
}

TEST_F(Unify, SqrtOfOddExponentIsNonInteger) {
  DimVarId d = u.add_variable("D");
  u.add_equation(DimTerm::variable(d, 2), DimTerm::of(dim({{"length", 3}})));
  UnifyResult res = u.solve();
  EXPECT_EQ(res.status, UnifyStatus::non_integer);
  EXPECT_EQ(res.variable, d);
  EXPECT_EQ(res.variables[d].state, VariableSolution::State::non_integer);
  EXPECT_EQ(u.explain(res, r), "D would be length^(3/2), which is not a dimension (exponents must be integers)");
}

TEST_F(Unify, PowWithIntegerConstantExponent) {
  // pow(x: float<D>, 3) = float<D^3>; result known, argument inferred.
  DimVarId d = u.add_variable("D");
  u.add_equation(DimTerm::variable(d, 3), DimTerm::of(dim({{"volume", 1}, {"time", -3}})));
  UnifyResult res = u.solve();
  ASSERT_TRUE(res.ok());
  EXPECT_EQ(r.format(res.variables[d].value), "velocity");
  EXPECT_EQ(r.format_product(res.variables[d].value, Notation::ascii), "length*time^-1");
}

TEST_F(Unify, DimensionlessSolution) {
  DimVarId d = u.add_variable("D");
  u.add_equation(term({{"length", 1}}, {{d, 1}}), DimTerm::of(dim({{"length", 1}})));
  UnifyResult res = u.solve();
  ASSERT_TRUE(res.ok());
  EXPECT_TRUE(res.variables[d].value.is_dimensionless());
}

TEST_F(Unify, MultipleVariables) {
  // mix-like generic: A * B = radiance, A / B = brdf
  DimVarId a = u.add_variable("A"), b = u.add_variable("B");
  u.add_equation(DimTerm{Dimension{}, {{a, 1}, {b, 1}}}, DimTerm::of(dim({{"radiance", 1}})));
  u.add_equation(DimTerm{Dimension{}, {{a, 1}, {b, -1}}}, DimTerm::of(dim({{"length", 2}})));
  UnifyResult res = u.solve();
  // A^2 = radiance·length² has odd exponents (energy¹) → non-integer
  EXPECT_EQ(res.status, UnifyStatus::non_integer);

  DimensionUnifier v;
  DimVarId x = v.add_variable("X"), y = v.add_variable("Y");
  v.add_equation(DimTerm{Dimension{}, {{x, 1}, {y, 1}}}, DimTerm::of(dim({{"radiance", 1}, {"proj", 1}})));
  v.add_equation(DimTerm::variable(y), DimTerm::of(dim({{"solid_angle", -1}})));
  UnifyResult ok = v.solve();
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(ok.variables[x].value, dim({{"irradiance", 1}}));
  EXPECT_EQ(v.explain(ok, r), "X = irradiance, Y = pdf_solid_angle");
}

TEST_F(Unify, VariablesOnBothSides) {
  // D * length = D^2 / time  →  D = length·time
  DimVarId d = u.add_variable("D");
  u.add_equation(term({{"length", 1}}, {{d, 1}}), term({{"time", -1}}, {{d, 2}}));
  UnifyResult res = u.solve();
  ASSERT_TRUE(res.ok());
  EXPECT_EQ(res.variables[d].value, dim({{"length", 1}, {"time", 1}}));
}

TEST_F(Unify, ConflictingConstraintIsTheFirstThatContradicts) {
  // max(a: float<D>, b: float<D>) with length and time
  DimVarId d = u.add_variable("D");
  u.add_equation(DimTerm::variable(d), DimTerm::of(dim({{"length", 1}})));
  u.add_equation(DimTerm::variable(d), DimTerm::of(dim({{"length", 1}})));  // redundant, fine
  u.add_equation(DimTerm::variable(d), DimTerm::of(dim({{"time", 1}})));
  UnifyResult res = u.solve();
  EXPECT_EQ(res.status, UnifyStatus::no_solution);
  EXPECT_EQ(res.conflicting_equation, 2u);
  EXPECT_TRUE(res.conflicting_base == *r.find_base("length") || res.conflicting_base == *r.find_base("time"));
  EXPECT_NE(u.explain(res, r).find("constraint 3 contradicts"), std::string::npos);
}

TEST_F(Unify, ConstantEquationsWithoutVariables) {
  u.add_equation(DimTerm::of(dim({{"radiance", 1}})), DimTerm::of(dim({{"irradiance", 1}, {"solid_angle", -1}, {"proj", -1}})));
  EXPECT_TRUE(u.solve().ok());
  u.add_equation(DimTerm::of(dim({{"radiance", 1}})), DimTerm::of(dim({{"irradiance", 1}})));
  UnifyResult res = u.solve();
  EXPECT_EQ(res.status, UnifyStatus::no_solution);
  EXPECT_EQ(res.conflicting_equation, 1u);
}

TEST_F(Unify, UnderDetermined) {
  DimVarId a = u.add_variable("A"), b = u.add_variable("B");
  u.add_equation(DimTerm{Dimension{}, {{a, 1}, {b, 1}}}, DimTerm::of(dim({{"length", 1}})));
  UnifyResult res = u.solve();
  EXPECT_EQ(res.status, UnifyStatus::underdetermined);
  EXPECT_EQ(res.variables[a].state, VariableSolution::State::free);
  EXPECT_EQ(u.explain(res, r), "A is not determined by the arguments");

  DimensionUnifier v;
  v.add_variable("Unused");
  EXPECT_EQ(v.solve().status, UnifyStatus::underdetermined);
}

TEST_F(Unify, PartiallyDeterminedKeepsTheDeterminedOnes) {
  DimVarId a = u.add_variable("A"), b = u.add_variable("B"), c = u.add_variable("C");
  u.add_equation(DimTerm::variable(a), DimTerm::of(dim({{"time", 1}})));
  u.add_equation(DimTerm{Dimension{}, {{b, 1}, {c, 1}}}, DimTerm::of(dim({{"length", 1}})));
  UnifyResult res = u.solve();
  EXPECT_EQ(res.status, UnifyStatus::underdetermined);
  EXPECT_EQ(res.variable, b);
  EXPECT_EQ(res.variables[a].state, VariableSolution::State::determined);
  EXPECT_EQ(res.variables[a].value, dim({{"time", 1}}));
}

TEST_F(Unify, ChainOfManyVariables) {
  // X0 = length, X(i+1) = X(i)^2 / length  → all X = length
  std::vector<DimVarId> xs;
  for (int i = 0; i < 50; ++i) xs.push_back(u.add_variable("X" + std::to_string(i)));
  u.add_equation(DimTerm::variable(xs[0]), DimTerm::of(dim({{"length", 1}})));
  for (int i = 0; i + 1 < 50; ++i)
    u.add_equation(DimTerm::variable(xs[i + 1]), term({{"length", -1}}, {{xs[i], 2}}));
  UnifyResult res = u.solve();
  ASSERT_TRUE(res.ok());
  for (DimVarId x : xs) EXPECT_EQ(res.variables[x].value, dim({{"length", 1}}));
}

TEST_F(Unify, LargeExponentsOverflowIsReported) {
  // X(i+1) = X(i)^2 with X0 = length²: exponents double each step and leave int64.
  std::vector<DimVarId> xs;
  for (int i = 0; i < 70; ++i) xs.push_back(u.add_variable("X" + std::to_string(i)));
  u.add_equation(DimTerm::variable(xs[0]), DimTerm::of(dim({{"length", 2}})));
  for (int i = 0; i + 1 < 70; ++i) u.add_equation(DimTerm::variable(xs[i + 1]), DimTerm::variable(xs[i], 2));
  EXPECT_EQ(u.solve().status, UnifyStatus::overflow);
}

TEST_F(Unify, SolutionsBeyondInt32ExponentsOverflow) {
  // X = length^(2^40) is exact in the solver but not an int32 exponent.
  DimVarId x = u.add_variable("X");
  DimVarId y = u.add_variable("Y");
  u.add_equation(DimTerm::variable(y), DimTerm::of(Dimension::base(0, 1 << 20)));
  u.add_equation(DimTerm::variable(x), DimTerm::variable(y, 1 << 20));
  UnifyResult res = u.solve();
  EXPECT_EQ(res.status, UnifyStatus::overflow);
  EXPECT_EQ(res.variable, x);
}

TEST(SpaceUnifier, BindsAndConflicts) {
  DimensionRegistry r;
  const SpaceId world = *r.add_space("world"), object = *r.add_space("object");
  SpaceUnifier s;
  auto a = s.add_variable("A"), b = s.add_variable("B");
  EXPECT_FALSE(s.resolve(SpaceTerm::variable(a)));
  EXPECT_TRUE(s.unify(SpaceTerm::variable(a), SpaceTerm::variable(b)));
  EXPECT_TRUE(s.unify(SpaceTerm::variable(b), SpaceTerm::space(world)));
  EXPECT_EQ(s.resolve(SpaceTerm::variable(a)), world);
  EXPECT_FALSE(s.unify(SpaceTerm::variable(a), SpaceTerm::space(object)));
  EXPECT_TRUE(s.unify(SpaceTerm::space(world), SpaceTerm::variable(a)));
  EXPECT_FALSE(s.unify(SpaceTerm::space(world), SpaceTerm::space(object)));
  EXPECT_EQ(s.variable_name(b), "B");
}

TEST(SpaceUnifier, JoiningBoundVariables) {
  SpaceUnifier s;
  auto a = s.add_variable("A"), b = s.add_variable("B"), c = s.add_variable("C");
  EXPECT_TRUE(s.unify(SpaceTerm::variable(a), SpaceTerm::space(3)));
  EXPECT_TRUE(s.unify(SpaceTerm::variable(c), SpaceTerm::variable(a)));
  EXPECT_TRUE(s.unify(SpaceTerm::variable(b), SpaceTerm::variable(c)));
  EXPECT_EQ(s.resolve(SpaceTerm::variable(b)), 3u);
  EXPECT_FALSE(s.unify(SpaceTerm::variable(b), SpaceTerm::space(4)));
}

}  // namespace
}  // namespace safegi
