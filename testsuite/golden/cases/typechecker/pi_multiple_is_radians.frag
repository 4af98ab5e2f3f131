#version 330 core
#include <safegi/prelude.sgl>
// A plain number made with a multiple of π is an angle in radians for sin,
// cos and tan (the azimuth 2π u of a sample, degrees times π / 180); a plain
// number without one still asks which unit it is in. Stored into a declared
// angle, such a number is radians too.
uniform float<1> u;
uniform float<1> degrees;
out vec4 c;
void main() {
    float phi = 6.283185307179586 * u;
    float fromDegrees = degrees * 3.141592653589793 / 180.0;
    float notAnAngle = 1.0 / 3.141592653589793;
    float<angle> azimuth = 6.283185307179586 * u;
    float<angle> plain = u;
    c = vec4(cos(phi), sin(phi), tan(fromDegrees), sin(degrees) + cos(notAnAngle));
}
