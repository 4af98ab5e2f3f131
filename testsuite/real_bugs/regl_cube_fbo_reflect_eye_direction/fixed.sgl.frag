#version 100
#include <safegi/prelude.sgl>
// A functional WebGL library's example: a teapot reflects a dynamically
// rendered cube map. GLSL's reflect() takes the incident direction (eye to
// surface), so the surface-to-eye vector is negated first.
precision mediump float;
space world;

uniform samplerCube<spectrum<radiance>> envMap;
uniform point<world> eye;

varying point<world, shaded> vPosition;
varying normal<world> vNormal;

void main() {
    vec3 N = normalize(vNormal);
    vec3 eyeDir = normalize(eye - vPosition);
    vec3 R = reflect(-eyeDir, N);
    spectrum<radiance> env = textureCube(envMap, R).rgb;
    gl_FragColor = vec4(env, 1.0);
}
