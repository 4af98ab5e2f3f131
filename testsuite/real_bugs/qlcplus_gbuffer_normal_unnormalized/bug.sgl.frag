#version 330 core
#include <safegi/prelude.sgl>
// A lighting-console's 3D preview shades spotlights in a deferred pass. The
// G-buffer stores the world normal as the geometry pass computed it (model
// matrix times the vertex normal, interpolated), so the lighting pass
// normalises the texel before the Lambert cosine.
space world;

uniform sampler2D<point<world>> positionTex;
uniform sampler2D<normal<world>> normalTex;
uniform sampler2D albedoTex;
uniform point<world> lightPos;
uniform vec3 lightColor;
uniform float<intensity> lightIntensity;

in vec2 fsUV;
out vec4 fragColor;

void main() {
    vec3 P = texture(positionTex, fsUV).xyz;
    vec3 N = texture(normalTex, fsUV).xyz;
    vec3 toLight = lightPos - P;
    vec3 L = normalize(toLight);
    float NdotL = max(dot(N, L), 0.0);
    float<irradiance> E = lightIntensity * inverse_square(length(toLight)) * NdotL;
    fragColor = vec4(texture(albedoTex, fsUV).rgb * lightColor * E, 1.0);
}
