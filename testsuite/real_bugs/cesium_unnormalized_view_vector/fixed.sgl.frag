#version 330 core
#include <safegi/prelude.sgl>
// Procedural image-based lighting in eye coordinates (the camera at the
// origin): the view vector is the unit vector from the surface to the eye,
// and N.V the cosine the split-sum lookup needs.
space eye : eye;                                 // eye coordinates: the camera at the origin
space world;

uniform rigidmap<eye, world> czm_inverseViewRotation;
uniform samplerCube<spectrum<radiance>> u_specularMap;
uniform sampler2D u_brdfLut;
uniform spectrum<1> f0;
uniform float<1> roughness;

in point<eye, shaded> positionEC;
in normal<eye> normalEC;
out vec4 fragColor;

void main() {
    vec3 v = -normalize(positionEC);
    vec3 n = normalize(normalEC);
    vec3 r = normalize(czm_inverseViewRotation * normalize(reflect(-v, n)));
    float NdotV = abs(dot(n, v)) + 0.001;
    vec2 brdfLut = texture(u_brdfLut, vec2(NdotV, 1.0 - roughness)).rg;
    vec3 specularIrradiance = textureLod(u_specularMap, r, roughness * 8.0).rgb;
    spectrum<radiance> specular = specularIrradiance * (f0 * brdfLut.x + brdfLut.y);
    fragColor = vec4(specular, 1.0);
}
