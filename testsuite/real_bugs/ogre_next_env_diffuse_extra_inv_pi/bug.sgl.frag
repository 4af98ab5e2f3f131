#version 330 core
#include <safegi/prelude.sgl>
// PBS shading where the material's diffuse colour carries the Lambert 1/pi
// (folded in once at material setup) and serves as the BRDF of the direct
// lights; the environment's diffuse term is a radiance per unit albedo, so it
// takes the colour without the 1/pi.
space world;

uniform spectrum<1> baseColour;
uniform direction<world> lightDir;                       // toward the light
uniform spectrum<irradiance / proj> lightDiffuse;
uniform samplerCube<spectrum<radiance>, world> irradianceEnv;   // cosine-convolved environment (E / pi)

in normal<world> vNormal;
out vec4 outColour;

const float PI = 3.14159265358979;

void main() {
    vec3 N = normalize(vNormal);
    vec3 diffuse = baseColour / PI;
    float NdotL = max(dot(N, lightDir), 0.0);
    vec3 direct = diffuse * lightDiffuse * NdotL;
    vec3 envD = texture(irradianceEnv, N).rgb;
    vec3 ambient = envD * diffuse;
    spectrum<radiance> colour = direct + ambient;
    outColour = vec4(colour, 1.0);
}
