// Dimension analysis: the literal policy, inference of unannotated locals,
// typed built-ins (sqrt, pow, trigonometry), generic functions and casts.

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace safegi::testing {
namespace {

using Messages = std::vector<std::string>;

Messages messages_of(std::string_view body, std::string_view globals = "") {
  std::string source = std::string(globals) + "\nvoid main() {\n" + std::string(body) + "\n}\n";
  return check_source(source)->messages();
}

TEST(Dimensions, AddingNeedsEqualDimensions) {
  EXPECT_EQ(messages_of("float<length> a = 1.0 * meter; float<time> t = 2.0 * second; float<length> b = a + a;"), Messages{});
  EXPECT_EQ(messages_of("float<length> a = 1.0 * meter; float<time> t = 2.0 * second; float x = a + t;"),
            Messages{"error: cannot add float<length> and float<time>"});
  EXPECT_EQ(messages_of("float<length> a = 1.0 * meter; float<time> t = 2.0 * second; bool b = a < t;"),
            Messages{"error: cannot compare float<length> and float<time>"});
}

TEST(Dimensions, MultiplicationCombinesDimensions) {
  EXPECT_EQ(messages_of("float<length> d = 2.0 * meter; float<time> t = 1.0 * second; float<velocity> v = d / t;"), Messages{});
  EXPECT_EQ(messages_of("float<length> d = 2.0 * meter; float<time> t = 1.0 * second; float<velocity> v = d * t;"),
            Messages{"error: cannot initialize 'v' of type float<velocity> with a value of type float<length·time>"});
  EXPECT_EQ(messages_of("float<length> d = 2.0 * meter; float<area> a = d * d; float<volume> v = a * d; float<1> r = v / (a * d);"),
            Messages{});
}

TEST(Dimensions, LiteralPolicy) {
  // Zero fits any dimension; other literals are dimensionless.
  EXPECT_EQ(messages_of("float<length> d = 0.0; spectrum<radiance> L = vec3(0.0); L = spectrum<radiance>(0.0); d = 0.0;"), Messages{});
  EXPECT_EQ(messages_of("float<length> d = 1.0;"),
            Messages{"error: cannot initialize 'd' of type float<length> with a value of type float<dimensionless>"});
  EXPECT_EQ(messages_of("float<length> d = 1.0 * meter; float<length> e = d + 1.0;"),
            Messages{"error: cannot add float<length> and float<dimensionless>"});
  EXPECT_EQ(messages_of("float<length> d = 1.0 * meter; float<length> e = 2.0 * d; if (d > 0.0) e = d;"), Messages{});
  // A literal in a constructor of an annotated type takes that annotation.
  EXPECT_EQ(messages_of("float<length> d = float<length>(1.0); spectrum<radiance> L = spectrum<radiance>(1.0, 0.5, 0.2);"), Messages{});
}

TEST(Dimensions, UnannotatedLocalsAreInferredFromTheirInitialiser) {
  auto c = check_source("space world; uniform normal<world> n; in direction<world> wi; void main() {\n"
                        "  float c = dot(n, wi);\n  float<length> d = 3.0 * meter;\n  float a = d * d;\n  vec3 zero = vec3(0.0);\n  float one = 1.0;\n}");
  EXPECT_EQ(c->rendered(), "");
  EXPECT_EQ(declared_type(*c, "c"), "float<proj>");
  EXPECT_EQ(declared_type(*c, "a"), "float<area>");
  EXPECT_EQ(declared_type(*c, "zero"), "vec3");  // a zero initialiser says nothing
  EXPECT_EQ(declared_type(*c, "one"), "float<dimensionless>");
}

// An unannotated local is a name, not a quantity: reused for another one in the same block
// it takes the new type from there on (the note says where); reused in a nested block it is
// unknown after it (either may reach a later use). An annotated variable never changes.
TEST(Dimensions, UnannotatedLocalsReusedForAnotherQuantityFollowTheAssignment) {
  auto bad = check_source("void main() {\n  float<length> d = 3.0 * meter;\n  float a = d * d;\n  a = d;\n  float<area> b = a;\n}");
  ASSERT_EQ(bad->diagnostics.diagnostics().size(), 1u) << bad->rendered();
  EXPECT_EQ(bad->diagnostics.diagnostics()[0].message,
            "cannot initialize 'b' of type float<area> with a value of type float<length>");
  EXPECT_EQ(bad->diagnostics.diagnostics()[0].notes.back().message, "type of 'a' set by this assignment as float<length>");
  EXPECT_EQ(messages_of("float<length> d = 3.0 * meter; float a = d * d; a *= 1.0 / d; float<length> e = a;"), Messages{});
  EXPECT_EQ(messages_of("float<length> d = 3.0 * meter; float a = d * d; if (d > 0.0) { a = d; } float<time> t = a;"),
            Messages{});  // unknown after the branch
  EXPECT_EQ(messages_of("float<length> d = 3.0 * meter; float<area> a = d * d; a = d;"),
            Messages{"error: cannot assign 'a' of type float<area> with a value of type float<length>"});
}

TEST(Dimensions, SqrtHalvesEvenExponentsAndRejectsOddOnes) {
  EXPECT_EQ(messages_of("float<area> a = 4.0 * meter * meter; float<length> d = sqrt(a); float<inv_length> i = inversesqrt(a);"),
            Messages{});
  EXPECT_EQ(messages_of("float<volume> v = 1.0 * meter * meter * meter; float x = sqrt(v);"),
            Messages{"error: cannot call 'sqrt' with (float<volume>): D would be length^(3/2), which is not a dimension "
                     "(exponents must be integers)"});
}

TEST(Dimensions, PowNeedsADimensionlessBaseOrAConstantIntegerExponent) {
  EXPECT_EQ(messages_of("float<length> d = 2.0 * meter; float<volume> v = pow(d, 3.0); float<area> a = pow(d, 2);"
                        "float<1> x = 0.5; float y = pow(x, 2.2);"),
            Messages{});
  EXPECT_EQ(messages_of("float<length> d = 2.0 * meter; float<1> e = 2.2; float x = pow(d, e);"),
            Messages{"error: pow of float<length> needs a constant integer exponent (or a dimensionless base)"});
  EXPECT_EQ(messages_of("float<length> d = 2.0 * meter; float x = pow(d, 2.5);"),
            Messages{"error: pow of float<length> needs a constant integer exponent (or a dimensionless base)"});
}

TEST(Dimensions, TrigonometryTakesAnglesAndReturnsNumbers) {
  EXPECT_EQ(messages_of("float<angle> a = 30.0 * degree; float s = sin(a); float<angle> b = acos(s); float<angle> c = atan(s, s);"
                        "float<angle> r = radians(45.0); float deg = degrees(r);"),
            Messages{});
  EXPECT_EQ(messages_of("float s = sin(30.0);"),
            Messages{"error: argument 1 of 'sin' has type float<dimensionless>, but 'sin' expects float<angle>"});
  // degrees() gives the angle in degrees, which sin() does not take.
  EXPECT_EQ(messages_of("float<angle> a = radians(30.0); float s = sin(degrees(a));"),
            Messages{"error: argument 1 of 'sin' has type float<angle in degree>, but 'sin' expects float<angle>"});
  EXPECT_EQ(messages_of("float<angle in degree> a = 30.0 * degree in degree; float<angle> r = radians(a); float<angle> b = radians(r);"),
            Messages{"error: argument 1 of 'radians' has type float<angle>, which is already in radians"});
  EXPECT_EQ(messages_of("float e = exp(2.0 * meter);"),
            Messages{"error: argument 1 of 'exp' has type float<length>, but 'exp' expects float<dimensionless>"});
}

TEST(Dimensions, MinMaxClampMixUnifyOneDimension) {
  EXPECT_EQ(messages_of("float<length> a = 1.0 * meter; float<length> b = max(a, 0.0); float<length> c = clamp(a, b, 2.0 * meter);"
                        "spectrum<radiance> L = spectrum<radiance>(1.0); spectrum<radiance> M = mix(L, L * 2.0, 0.5);"),
            Messages{});
  EXPECT_EQ(messages_of("float<length> a = 1.0 * meter; float<time> t = 1.0 * second; float m = max(a, t);"),
            Messages{"error: argument 2 of 'max' has type float<time>, but the other arguments make it float<length>"});
}

TEST(Dimensions, GenericFunctionsAreInstantiatedAtEachCall) {
  const char* globals =
      "template<dimension D> float<D> twice(float<D> x) { return x + x; }\n"
      "template<dimension D> float<D> root(float<D*D> x) { return sqrt(x); }\n"
      "template<dimension D, dimension E> float<D*E> times(float<D> a, float<E> b) { return a * b; }\n";
  EXPECT_EQ(messages_of("float<length> d = twice(2.0 * meter); float<time> t = twice(1.0 * second);"
                        "float<length> r = root(d * d); float<area> a = times(d, d);",
                        globals),
            Messages{});
  EXPECT_EQ(messages_of("float<time> t = twice(2.0 * meter);", globals),
            Messages{"error: cannot initialize 't' of type float<time> with a value of type float<length>"});
  EXPECT_EQ(messages_of("float<length> r = root(2.0 * meter);", globals),
            Messages{"error: cannot call 'root' with (float<length>): D would be length^(1/2), which is not a dimension "
                     "(exponents must be integers)"});
  // Inside a generic body the parameters are rigid.
  EXPECT_EQ(messages_of("", "template<dimension D> float<D> wrong(float<D> x) { return x * x; }"),
            Messages{"error: cannot return a value of type float<D^2> from 'wrong', which returns float<D>"});
}

TEST(Dimensions, CastsAreExplicitAndAccepted) {
  EXPECT_EQ(messages_of("float<area> A = 1.0 * meter * meter; float<length> d = 2.0 * meter;"
                        "float<solid_angle> dw = float<solid_angle>(A / (d * d));"),
            Messages{});
}

TEST(Dimensions, CompoundAssignmentKeepsTheDimension) {
  EXPECT_EQ(messages_of("spectrum<radiance> sum = spectrum<radiance>(0.0); spectrum<radiance> L = spectrum<radiance>(1.0);"
                        "sum += L; sum *= 0.5; sum /= 2.0;"),
            Messages{});
  EXPECT_EQ(messages_of("float<length> d = 1.0 * meter; d *= d;"),
            Messages{"error: cannot assign 'd' of type float<length> with a value of type float<area>"});
}

TEST(Dimensions, UnannotatedValuesAreConsistentWithEverything) {
  EXPECT_EQ(messages_of("float<length> d = 1.0 * meter; d = u; float x = u * d; d = x; spectrum<radiance> L = c;",
                        "uniform float u; uniform vec3 c;"),
            Messages{});
}

TEST(Dimensions, ErrorsDoNotCascade) {
  EXPECT_EQ(messages_of("float<length> d = 1.0 * meter; float<time> t = 1.0 * second; float<length> e = (d + t) * 2.0 + d;"
                        "float<area> a = e * e; a = undefined_name + a * 3.0;"),
            (Messages{"error: cannot add float<length> and float<time>", "error: use of undeclared identifier 'undefined_name'"}));
}

}  // namespace
}  // namespace safegi::testing
