#version 330 core
#include <safegi/prelude.sgl>
// A DCC viewport's USD preview surface, image-based specular: the environment
// is reflected symmetrically about the normal, so the half vector is the
// normal itself and Schlick's Fresnel takes N.E, not E.H of a punctual light.
space world;

uniform samplerCube<spectrum<radiance>> specularEnv;
uniform point<world> eyePosition;
uniform direction<world, away> lightDirection;   // the last punctual light, toward it
uniform spectrum<1> specularColor;                // F0

in point<world, shaded> worldPosition;
in normal<world> worldNormal;
out vec4 fragColor;

vec3 schlick(vec3 f0, float cosTheta) {
    return f0 + (vec3(1.0) - f0) * pow(1.0 - cosTheta, 5.0);
}

void main() {
    vec3 N = normalize(worldNormal);
    vec3 E = normalize(eyePosition - worldPosition);
    vec3 H = normalize(lightDirection + E);
    vec3 R = reflect(-E, N);
    spectrum<1> F = schlick(specularColor, max(dot(E, H), 0.0));
    spectrum<radiance> envSpec = F * texture(specularEnv, R).rgb;
    fragColor = vec4(envSpec, 1.0);
}
