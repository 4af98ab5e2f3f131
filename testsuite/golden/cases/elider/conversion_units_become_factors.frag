#version 330 core
#include <safegi/prelude.sgl>
// A unit conversion is a multiplication by a literal; to the same scale, nothing.
unit hour : time = 3600.0;
uniform float<length in centimeter> radiusCm;
uniform float<angle in degree> fovDeg;
uniform float<velocity in kilometer / hour> speed;
uniform spectrum<power in watt> flux;
out vec4 c;
void main() {
  float<length> r = radiusCm in meter;
  float<area> a = (radiusCm * radiusCm) in (meter^2);  // in binds tighter than *
  float<angle> half_fov = 0.5 * fovDeg in radian;
  float<velocity> v = speed in (meter / second);
  spectrum<power> f = flux in watt;
  float<length in millimeter> mm = radiusCm
      in millimeter;
  c = vec4(r + float(mm) * 0.0, a, tan(half_fov), v) + vec4(f, 0.0);
}
