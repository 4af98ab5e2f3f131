#version 300 es
#include <safegi/prelude.sgl>
// A WebGL 2 book's projection-modes example: its field-of-view slider is in
// degrees, while the math library's perspective() takes radians, so the value
// is converted before the projection's focal scale 1 / tan(fov / 2) is taken.
precision highp float;
space object;
space view;

uniform float<angle in degree> fov;
uniform float aspect;
uniform float<length> near;
uniform float<length> far;
uniform map<object, view> uModelViewMatrix;

in point<object> aVertexPosition;

void main() {
    vec3 p = (uModelViewMatrix * vec4(aVertexPosition, 1.0)).xyz;
    float f = 1.0 / tan(fov / 2.0);
    float nf = 1.0 / (near - far);
    gl_Position = vec4(p.x * f / aspect, p.y * f, (far + near) * nf * p.z + 2.0 * far * near * nf, -p.z);
}
