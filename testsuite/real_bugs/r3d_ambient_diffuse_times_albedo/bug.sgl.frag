#version 330 core
#include <safegi/prelude.sgl>
// A deferred renderer's ambient pass: it writes the ambient irradiance
// reaching each pixel into the diffuse-light target and the ambient specular
// into another; the scene pass multiplies the diffuse target by the surface's
// albedo (over pi) once. Albedo is read here only for the specular F0.
uniform sampler2D texAlbedo;
uniform sampler2D texORM;             // occlusion, roughness, metalness
uniform spectrum<irradiance> uAmbientIrradiance;
uniform spectrum<radiance> uAmbientRadiance;   // prefiltered, averaged

in vec2 vTexCoord;
layout(location = 0) out vec4 fragDiffuse;    // irradiance; albedo applied later
layout(location = 1) out vec4 fragSpecular;

void main() {
    spectrum<1> albedo = spectrum<1>(texture(texAlbedo, vTexCoord).rgb);
    vec3 orm = texture(texORM, vTexCoord).rgb;
    float occlusion = orm.r;
    float metalness = orm.b;
    spectrum<1> F0 = mix(spectrum<1>(0.04), albedo, metalness);
    spectrum<irradiance> diffuse = uAmbientIrradiance * albedo * occlusion * (1.0 - metalness);
    spectrum<radiance> specular = uAmbientRadiance * F0 * occlusion;
    fragDiffuse = vec4(diffuse, 1.0);
    fragSpecular = vec4(specular, 1.0);
}
