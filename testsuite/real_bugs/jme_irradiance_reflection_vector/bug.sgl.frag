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
    normal<world> normal = normalize(wNormal);
    direction<world, away> viewDir = normalize(g_CameraPosition - wPosition);
    direction<world, away> rv = reflect(-viewDir, normal);
    spectrum<radiance> indirectDiffuse = texture(g_IrradianceMap, rv).rgb * diffuseColor;
    spectrum<radiance> indirectSpecular = textureLod(g_PrefEnvMap, rv, roughness * 6.0).rgb * specularColor;
    fragColor = vec4(indirectDiffuse + indirectSpecular, 1.0);
}
