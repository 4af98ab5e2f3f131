#version 300 es
#include <safegi/prelude.sgl>
// A creative-coding library's lit vertex shader shades in view space (the
// normal matrix is that of model-view); a directional light is given in world
// coordinates, so its direction is rotated by the camera before the cosine.
precision highp float;
space object;
space world;
space view;
space clip;

uniform map<object, view> uModelViewMatrix;
uniform projmap<view, clip> uProjectionMatrix;
uniform mat3<object, view, normal> uNormalMatrix;
uniform rigidmap<world, view> uViewMatrix;
uniform direction<world, toward> uLightingDirection;   // the way the light travels
uniform vec3 uDirectionalColor;

in point<object> aPosition;
in normal<object> aNormal;
out vec3 vDiffuseColor;

void main() {
    vec3 N = normalize(uNormalMatrix * aNormal);
    vec3 L = uLightingDirection;
    float diffuse = max(0.0, dot(N, -L));
    vDiffuseColor = uDirectionalColor * diffuse;
    gl_Position = uProjectionMatrix * uModelViewMatrix * vec4(aPosition, 1.0);
}
