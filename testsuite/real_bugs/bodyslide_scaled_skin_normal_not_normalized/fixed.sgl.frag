#version 330 core
#include <safegi/prelude.sgl>
// A mesh editor's preview of skinned game meshes: the vertex stage carries the
// normal to view space through a global-to-skin transform that may scale, so
// the fragment stage normalizes it before the diffuse and rim terms.
space view : eye;

uniform direction<view> lightDirection;           // toward the light
uniform spectrum<irradiance / proj> lightColor;
uniform spectrum<brdf> diffuseBrdf;               // albedo / pi
uniform float rimStrength;

in point<view, shaded> vPosition;
in normal<view> vNormal;
out vec4 fragColor;

void main() {
    vec3 n = normalize(vNormal);
    vec3 v = normalize(-vPosition);
    float NdotL = max(dot(n, lightDirection), 0.0);
    spectrum<radiance> diffuse = diffuseBrdf * lightColor * NdotL;
    float rim = pow(1.0 - max(dot(n, v), 0.0), 4.0) * rimStrength;
    fragColor = vec4(diffuse + diffuse * rim, 1.0);
}
