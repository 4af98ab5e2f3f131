#version 330 core
#include <safegi/prelude.sgl>
// A quantity in a unit times that unit's scale is the quantity in reference
// units, the conversion written out: degrees times pi / 180 are radians,
// centimetres times 0.01 metres. Another factor keeps the unit.
uniform float<angle in degree> fovDeg;
uniform float<length in centimeter> radiusCm;
out vec4 c;
void main() {
    float t = tan(fovDeg * (3.141592653589793 / 180.0) * 0.5);
    float<length> r = radiusCm * 0.01;
    float<length> wrong = radiusCm * 0.1;
    c = vec4(t, r / meter, wrong / meter, 1.0);
}
