#version 330 core
#include <safegi/prelude.sgl>
// A Python GL binding's perspective example: the math library's perspective
// takes the vertical field of view in radians (the older helper it replaced
// took degrees), so the example's field of view is converted first.
space object;
space world;
space view;

uniform map<object, world> model;
uniform map<world, view> camera;
uniform float aspect;

const float<length> NEAR = float<length>(0.1);
const float<length> FAR = float<length>(1000.0);

in point<object> in_vert;

vec4 perspective(vec3 p, float<angle> fovy, float aspectRatio, float<length> zNear, float<length> zFar) {
    float f = 1.0 / tan(fovy / 2.0);
    float a = (zFar + zNear) / (zNear - zFar);
    float<length> b = 2.0 * zFar * zNear / (zNear - zFar);
    return vec4(p.x * f / aspectRatio, p.y * f, p.z * a + b, -p.z);
}

void main() {
    vec3 p = (camera * model * vec4(in_vert, 1.0)).xyz;
    gl_Position = perspective(p, 45.0, aspect, NEAR, FAR);
}
