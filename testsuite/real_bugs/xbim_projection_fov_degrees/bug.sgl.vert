#version 300 es
#include <safegi/prelude.sgl>
// A BIM viewer's vertex shader with its own perspective projection: the
// camera's field of view is kept in degrees (as the UI and the comparison
// with the effective field of view use it); the focal scale is the cotangent
// of half of it in radians.
precision highp float;
space object;
space view;

uniform map<object, view> modelView;
uniform float<angle in degree> fov;                  // vertical
uniform float aspect;
uniform float<length> zNear;
uniform float<length> zFar;

in point<object> aPosition;

void main() {
    vec3 p = (modelView * vec4(aPosition, 1.0)).xyz;
    float f = 1.0 / tan(fov * 0.5);
    float depthScale = (zFar + zNear) / (zNear - zFar);
    float depthOffset = 2.0 * zFar * zNear / (zNear - zFar);
    gl_Position = vec4(p.x * f / aspect, p.y * f, p.z * depthScale + depthOffset, -p.z);
}
