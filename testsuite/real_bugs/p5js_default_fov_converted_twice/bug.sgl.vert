#version 300 es
#include <safegi/prelude.sgl>
// A creative-coding library's perspective(): a field of view given by the
// user is in the sketch's angle mode (degrees here) and is converted to
// radians; the default field of view is already stored in radians and is
// used as it is.
precision highp float;
space object;
space view;

uniform map<object, view> uModelViewMatrix;
uniform bool uHasUserFov;
uniform float<angle in degree> uUserFovy;
uniform float<angle> uDefaultCameraFov;
uniform float uAspect;
uniform float<length> uNear;
uniform float<length> uFar;

in point<object> aPosition;

void main() {
    float<angle> fovy = radians(uHasUserFov ? uUserFovy : uDefaultCameraFov);
    float f = 1.0 / tan(fovy / 2.0);
    vec3 p = (uModelViewMatrix * vec4(aPosition, 1.0)).xyz;
    float depthScale = (uFar + uNear) / (uNear - uFar);
    float depthOffset = 2.0 * uFar * uNear / (uNear - uFar);
    gl_Position = vec4(p.x * f / uAspect, p.y * f, p.z * depthScale + depthOffset, -p.z);
}
