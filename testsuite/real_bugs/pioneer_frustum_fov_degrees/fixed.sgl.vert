#version 330 core
#include <safegi/prelude.sgl>
// A space game's frustum: the camera's field of view is kept in degrees, and
// the frustum (which once converted internally) now takes radians, so the
// caller converts before building it; the projection's focal scale is the
// cotangent of half the angle.
space object;
space view;

uniform map<object, view> modelView;
uniform float<angle in degree> fovDeg;           // vertical
uniform float width;
uniform float height;
uniform float<length> znear;
uniform float<length> zfar;

in point<object> position;

vec4 frustumProject(vec3 p, float<angle> fovAng, float aspect, float<length> n, float<length> f) {
    float scale = 1.0 / tan(fovAng * 0.5);
    float a = (f + n) / (n - f);
    float<length> b = 2.0 * f * n / (n - f);
    return vec4(p.x * scale / aspect, p.y * scale, p.z * a + b, -p.z);
}

void main() {
    vec3 p = (modelView * vec4(position, 1.0)).xyz;
    gl_Position = frustumProject(p, radians(fovDeg), width / height, znear, zfar);
}
