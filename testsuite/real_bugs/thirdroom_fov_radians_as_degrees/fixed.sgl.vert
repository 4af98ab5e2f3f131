#version 330 core
#include <safegi/prelude.sgl>
// A world-preview camera built from a glTF perspective camera, whose yfov is
// in radians (glTF's unit); the projection's focal scale is 1 / tan(yfov / 2).
space view;
space clip;

uniform float<angle> yfov;                          // glTF camera.perspective.yfov
uniform float<1> aspectRatio;
uniform float<length> znear;
uniform float<length> zfar;

in point<view> viewPosition;
out float<1> focal;

void main() {
    float<1> f = 1.0 / tan(yfov / 2.0);
    focal = f;
    float z = viewPosition.z;
    gl_Position = vec4(f / aspectRatio * viewPosition.x, f * viewPosition.y,
                       ((zfar + znear) * z + 2.0 * zfar * znear) / (znear - zfar), -viewPosition.z);
}
