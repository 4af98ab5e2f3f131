// User-function overload resolution: GLSL 4.00 §6.1 ranking of implicit
// conversions, and conversions of out parameters (parameter -> argument).

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace safegi::testing {
namespace {

using Messages = std::vector<std::string>;

Messages plain(std::string_view source) { return check_source(source, {.stage = Stage::vertex, .prelude = false})->messages(); }

TEST(Overloads, ExactMatchBeatsAConversion) {
  EXPECT_EQ(plain("float f(float x) { return x; } int f(int x) { return x; } void main() { int a = f(1); float b = f(1.0); }"),
            Messages{});
}

TEST(Overloads, IntToFloatBeatsIntToDouble) {
  EXPECT_EQ(plain("float f(float x) { return x; } double f(double x) { return x; } void main() { float a = f(1); double b = f(1.0lf); }"),
            Messages{});
  // The chosen overload's result type shows: f(1) is f(float), so its result is float, not double.
  EXPECT_EQ(plain("float f(float x) { return x; } double f(double x) { return x; } void main() { int a = f(1); }"),
            Messages{"error: cannot initialize 'a' of type int with a value of type float"});
}

TEST(Overloads, FloatToDoubleIsTheOnlyConversionOfAFloat) {
  EXPECT_EQ(plain("double f(double x) { return x; } int f(int x) { return x; } void main() { double a = f(1.0); }"), Messages{});
}

TEST(Overloads, AmbiguousCallsAreReported) {
  auto c = check_source(
      "void f(float a, double b) {}\nvoid f(double a, float b) {}\nvoid main() { f(1, 1); }\n",
      {.stage = Stage::vertex, .prelude = false});
  EXPECT_EQ(c->rendered(),
            "test.frag:3:15: error: call to 'f(int<1>, int<1>)' is ambiguous [E-AMBIGUOUS-CALL]\n"
            "void main() { f(1, 1); }\n"
            "              ^\n"
            "help: GLSL prefers an exact match, then float→double, then int→float over int→double\n"
            "test.frag:1:6: note: candidate: f(float, double)\n"
            "void f(float a, double b) {}\n"
            "     ^\n"
            "test.frag:2:6: note: candidate: f(double, float)\n"
            "void f(double a, float b) {}\n"
            "     ^\n");
  // int -> uint and int -> float are neither better than the other.
  EXPECT_EQ(plain("void g(uint a) {} void g(float a) {} void main() { g(1); }"),
            Messages{"error: call to 'g(int<1>)' is ambiguous"});
}

TEST(Overloads, OutParametersConvertBackToTheArgument) {
  // piglit glsl-1.20/compiler/qualifiers/out-conversion-int-to-float.vert: int -> float on the way out.
  EXPECT_EQ(plain("void f(out int x) { x = 0; } void main() { float y; f(y); }"), Messages{});
  EXPECT_EQ(plain("void f(out float x) { x = 0.0; } void main() { int y; f(y); }"),
            Messages{"error: no matching function for call to 'f(int)'"});
  EXPECT_EQ(plain("void f(inout int x) { x = 0; } void main() { float y; f(y); }"),
            Messages{"error: no matching function for call to 'f(float)'"});
}

}  // namespace
}  // namespace safegi::testing
