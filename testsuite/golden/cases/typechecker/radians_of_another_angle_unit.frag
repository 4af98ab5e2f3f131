#version 330 core
#include <safegi/prelude.sgl>
// radians() scales by π/180 and degrees() by 180/π: right for degrees and
// radians only. An angle in a third unit converts with `in`; a plain number
// of radians is given its unit before degrees().
unit arcminute : angle = degree / 60.0;
uniform float<angle in arcminute> tilt;
uniform float<1> turnRadians;
out vec4 c;
out vec2 fixedAngles;
void main() {
  float<angle> t = radians(tilt);
  float<angle in degree> tiltDeg = degrees(tilt);
  float<angle in degree> turnDeg = degrees(turnRadians);
  float<angle> fixedT = tilt in radian;
  float<angle in degree> fixedDeg = tilt in degree;
  float<angle in degree> fixedTurn = degrees(turnRadians * radian);
  c = vec4(float(t), float(tiltDeg), float(turnDeg), float(fixedT));
  fixedAngles = vec2(float(fixedDeg), float(fixedTurn));
}
