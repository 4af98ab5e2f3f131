#version 300 es
#include <safegi/prelude.sgl>
// Image-based lighting from spherical harmonics: the coefficients encode the
// irradiance arriving at a surface as a function of its normal, so the
// diffuse term evaluates them at the normal; the reflection vector is for the
// specular lookup only.
precision highp float;
space world;

uniform spectrum<irradiance> shCoefficients[4];      // bands 0 and 1
uniform samplerCube<spectrum<radiance>, world> specularMap;
uniform spectrum<brdf> diffuseBrdf;                   // albedo / pi
uniform spectrum<1> specularColor;

in point<world, shaded> vPosition;
in normal<world> vNormal;
uniform point<world> cameraPosition;
out vec4 fragColor;

spectrum<irradiance> evaluateSH(normal<world> d) {
    return shCoefficients[0] + shCoefficients[1] * d.y + shCoefficients[2] * d.z + shCoefficients[3] * d.x;
}

void main() {
    vec3 n = normalize(vNormal);
    vec3 v = normalize(cameraPosition - vPosition);
    vec3 r = reflect(-v, n);
    vec3 diffuse = diffuseBrdf * evaluateSH(n);
    spectrum<radiance> specular = specularColor * texture(specularMap, r).rgb;
    fragColor = vec4(diffuse + specular, 1.0);
}
