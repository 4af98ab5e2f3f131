#version 300 es
#include <safegi/prelude.sgl>
// Web engine's shading normal: getNormal() returns the world-space vertex
// normal as interpolated across the triangle, renormalized, and diffuse
// lighting uses it.
precision highp float;
space world;

uniform direction<world> u_lightDirection;   // the direction the light travels
uniform vec3 u_lightColor;
uniform vec3 u_diffuseColor;

in normal<world> v_normal;
out vec4 fragColor;

normal<world> getNormal() {
    vec3 n = normalize(v_normal);
    return n;
}

void main() {
    vec3 N = getNormal();
    float NdotL = max(dot(N, -u_lightDirection), 0.0);
    fragColor = vec4(u_diffuseColor * u_lightColor * NdotL, 1.0);
}
