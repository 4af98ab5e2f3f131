#version 330 core
#include <safegi/prelude.sgl>
// An astronomy visualisation's model renderer (spacecraft, asteroids): the
// fragment is shaded by the Sun in view space and also written to the
// deferred G-buffer that the atmosphere pass reads, whose positions and
// normals are in view (camera) space. The G-buffer's normal keeps its three
// coordinates here (the original stores it in a vec4 with w = 1, unused).
space object;
space view : eye;

in vec2 vs_st;
in normal<view> vs_normalViewSpace;
in normal<object> vs_normalObjSpace;
in point<view> vs_positionCameraSpace;
in float vs_screenSpaceDepth;

uniform bool performShading;
uniform direction<view> directionToSunViewSpace;
uniform sampler2D texture1;
uniform float opacity;

layout(location = 0) out vec4 color;
layout(location = 1) out point<view> gPosition;
layout(location = 2) out normal<view> gNormal;

void main() {
    vec3 diffuseAlbedo = texture(texture1, vs_st).rgb;
    if (performShading) {
        vec3 n = normalize(vs_normalViewSpace);
        vec3 l = directionToSunViewSpace;
        float diffuseCosineFactor = dot(n, l);
        vec3 ambientColor = 0.2 * diffuseAlbedo;
        vec3 diffuseColor = diffuseAlbedo * max(diffuseCosineFactor, 0.0);
        color = vec4(ambientColor + diffuseColor, opacity);
    } else {
        color = vec4(diffuseAlbedo, opacity);
    }
    gl_FragDepth = vs_screenSpaceDepth;
    gPosition = vs_positionCameraSpace;
    gNormal = vs_normalObjSpace;
}
