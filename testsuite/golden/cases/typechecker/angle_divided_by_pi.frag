#version 450
#include <safegi/prelude.sgl>
// An angle divided by a π constant is divided by π radians: a plain fraction
// (a lat-long map's u = φ / 2π, an angle normalised to [0, 1]), so adding it
// to an angle that was not divided is refused.
space world;
const float PI = 3.14159265358979;
const float HALF_PI = 1.5707963267949;
uniform direction<world> d;
uniform float<angle> sliceAngle;
uniform float<angle> horizon;
out vec4 color;
void main() {
    float u = atan(d.z, d.x) / (2.0 * PI) + 0.5;
    float n = (sliceAngle + HALF_PI) / PI;
    float covered = horizon / PI + n;
    float wrong = horizon + n;
    color = vec4(u, n, covered, wrong);
}
