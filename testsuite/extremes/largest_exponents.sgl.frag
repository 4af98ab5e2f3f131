#version 330 core
#include <safegi/prelude.sgl>
// The largest exponents: a literal exponent is at most 1000 (the parser's
// limit), and powers of derived dimensions reach 2^31 - 1 = 2147483647.
dimension kilo = length^1000;
dimension mega = kilo^1000;
dimension giga = mega^1000;                       // length^1000000000
dimension huge = giga * giga * mega^147 * kilo^483 * length^647;   // length^2147483647
dimension tiny = huge^-1;
out vec4 fragColor;

void main() {
    float<huge> a = float<huge>(2.0);
    float<tiny> b = float<tiny>(0.5);
    float<1> c = a * b;
    float<huge / length> d = a / float<length>(1.0);
    fragColor = vec4(c, d * b * float<length>(1.0), 0.0, 1.0);
}
