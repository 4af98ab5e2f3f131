#version 330 core
#include <safegi/prelude.sgl>
// A god game's camera: the horizontal field of view is turned into the
// vertical one for the projection. tan(xFov / 2) is the frustum's half-width
// over its depth; divided by the aspect ratio it is the half-height over the
// depth; its arctangent is the vertical half-angle, and twice that is the
// vertical field of view.
space object_s;
space view;

uniform map<object_s, view> modelView;
uniform float<angle> xFov;
uniform float aspect;                 // width / height
uniform float<length> znear;
uniform float<length> zfar;

in point<object_s> position;

void main() {
    float yFov = atan(2.0 * tan(xFov * 0.5) / aspect);
    float f = 1.0 / tan(yFov * 0.5);
    vec3 p = (modelView * vec4(position, 1.0)).xyz;
    float a = (zfar + znear) / (znear - zfar);
    float<length> b = 2.0 * zfar * znear / (znear - zfar);
    gl_Position = vec4(p.x * f / aspect, p.y * f, p.z * a + b, -p.z);
}
