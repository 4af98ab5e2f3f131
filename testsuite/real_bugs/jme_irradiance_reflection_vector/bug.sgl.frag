#version 330 core
#include <safegi/prelude.sgl>
// A PBR lighting shader's image-based part: diffuse light comes from the
// irradiance map looked up along the surface normal, specular light from the
// prefiltered map along the reflection vector.
space world;

uniform samplerCube<spectrum<radiance>> g_IrradianceMap;   // cosine-convolved (E / pi)
uniform samplerCube<spectrum<radiance>> g_PrefEnvMap;
uniform point<world> g_CameraPosition;
uniform spectrum<1> diffuseColor;
uniform spectrum<1> specularColor;
uniform float<1> roughness;

in point<world, shaded> wPosition;
in normal<world> wNormal;
out vec4 fragColor;

void main() {
    vec3 normal = normalize(wNormal);
    vec3 viewDir = normalize(g_CameraPosition - wPosition);
    vec3 rv = reflect(-viewDir, normal);
    vec3 indirectDiffuse = texture(g_IrradianceMap, rv).rgb * diffuseColor;
    spectrum<radiance> indirectSpecular = textureLod(g_PrefEnvMap, rv, roughness * 6.0).rgb * specularColor;
    fragColor = vec4(indirectDiffuse + indirectSpecular, 1.0);
}
