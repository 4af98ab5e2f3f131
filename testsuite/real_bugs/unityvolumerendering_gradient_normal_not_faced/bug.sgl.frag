#version 330 core
#include <safegi/prelude.sgl>
// Lighting in a direct volume renderer: the normal is the normalized density
// gradient, whose sign says which side is denser, not which side the viewer
// is on; it is turned toward the eye before the diffuse and Phong terms.
space object;

uniform sampler3D gradientTex;
uniform direction<object> lightDir;                      // toward the light
uniform float<1> specularIntensity;

in vec3 texPos;
in direction<object> eyeDir;                             // toward the eye
in vec4 sampleColour;
out vec4 fragColor;

vec3 calculateLighting(vec3 col, normal<object> normal, direction<object> lightDir, direction<object> eyeDir, float<1> specularIntensity) {
    float ndotl = max(mix(0.0, 1.5, dot(normal, lightDir)), 0.5);
    vec3 diffuse = ndotl * col;
    vec3 r = normalize(reflect(-lightDir, normal));
    float rdotv = max(dot(r, eyeDir), 0.0);
    vec3 specular = pow(rdotv, 32.0) * vec3(1.0, 1.0, 1.0) * specularIntensity;
    return diffuse + specular;
}

void main() {
    vec3 gradient = texture(gradientTex, texPos).xyz * 2.0 - 1.0;
    normal<object> n = normalize(gradient);
    vec3 lit = calculateLighting(sampleColour.rgb, n, lightDir, eyeDir, specularIntensity);
    fragColor = vec4(lit, sampleColour.a);
}
