#version 330 core
#include <safegi/prelude.sgl>
// Exponent arithmetic beyond 32 bits is an error, never a wrap-around.
dimension kilo = length^1000;
dimension mega = kilo^1000;
dimension giga = mega^1000;
dimension huge = giga * giga * mega^147 * kilo^483 * length^647;
dimension over = huge * length;
dimension over_power = giga^3;
dimension too_small = huge^-1 / length^2;
out vec4 fragColor;

void main() {
    float<giga> a = float<giga>(2.0);
    float<1> b = a * a * a;
    float<huge> h = float<huge>(1.0);
    float<1> c = h / float<inv_length>(1.0);
    fragColor = vec4(b, c, pow(a, 3), 1.0);
}
