// Constant folding where the checker needs constants: pow's integer exponent
// (float constants, const variables, arithmetic on them) and array sizes.

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace safegi::testing {
namespace {

using Messages = std::vector<std::string>;

Messages messages_of(std::string_view source) { return check_source(source)->messages(); }

TEST(Constants, PowExponentFromAConstVariable) {
  EXPECT_EQ(messages_of("const float N = 3.0; uniform float<length> d;"
                        "void main() { float<volume> v = pow(d, N); float<area> a = pow(d, N - 1.0); float<length> l = pow(d, N / 3.0); }"),
            Messages{});
  EXPECT_EQ(messages_of("const int K = 2; uniform float<length> d; void main() { float<area> a = pow(d, float(K)); }"), Messages{});
  EXPECT_EQ(messages_of("const float N = 3.0; uniform float<length> d; void main() { float<area> a = pow(d, N); }"),
            Messages{"error: cannot initialize 'a' of type float<area> with a value of type float<volume>"});
  // Not constant: a uniform, a non-const variable, a non-integer constant.
  EXPECT_EQ(messages_of("uniform float n; uniform float<length> d; void main() { float x = pow(d, n); }"),
            Messages{"error: pow of float<length> needs a constant integer exponent (or a dimensionless base)"});
  EXPECT_EQ(messages_of("const float H = 1.5; uniform float<length> d; void main() { float x = pow(d, H); }"),
            Messages{"error: pow of float<length> needs a constant integer exponent (or a dimensionless base)"});
}

TEST(Constants, ArraySizesFromFloatConstants) {
  EXPECT_EQ(messages_of("const float HALF = 4.0; void main() { float a[int(HALF * 0.5)]; float x = a[1]; }"), Messages{});
  EXPECT_EQ(messages_of("const float HALF = 4.0; void main() { float a[int(HALF * 0.5)]; float x = a[2]; }"),
            Messages{"error: index 2 is out of range for float[2]"});
}

}  // namespace
}  // namespace safegi::testing
