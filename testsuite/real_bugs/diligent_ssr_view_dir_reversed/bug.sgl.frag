#version 450
#include <safegi/prelude.sgl>
// A glTF viewer's post-effects pass that blends screen-space reflections with
// image-based lighting: the view direction is rebuilt per pixel from a point
// on the pixel's eye ray (NDC through the inverse view-projection, divided by
// w) and must point from the surface toward the camera, as the split-sum IBL
// lookup (N.V and the reflection of -V) expects.
space world;
space clip;

uniform projmap<clip, world> mViewProjInv;
uniform point<world> cameraPos;
uniform samplerCube<spectrum<radiance>, world> g_PrefilteredEnvMap;
uniform sampler2D g_PreintegratedGGX;
uniform sampler2D<normal<world>> g_tex2DNormal;
uniform sampler2D g_tex2DMaterial;           // r: roughness, g: metallic
uniform sampler2D g_tex2DBaseColor;
uniform sampler2D<spectrum<radiance>> g_tex2DSSR;
uniform float g_PrefilteredMips;

in vec2 vNormalizedXY;
out vec4 fragColor;

spectrum<radiance> iblSpecular(normal<world> N, direction<world, away> V, vec3 F0, float roughness) {
    direction<world> R = reflect(-V, N);
    float NdotV = clamp(dot(N, V), 0.0, 1.0);
    vec2 brdf = texture(g_PreintegratedGGX, vec2(NdotV, roughness)).rg;
    spectrum<radiance> prefiltered = textureLod(g_PrefilteredEnvMap, R, roughness * g_PrefilteredMips).rgb;
    return prefiltered * (F0 * brdf.x + brdf.y);
}

void main() {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    normal<world> N = texelFetch(g_tex2DNormal, pix, 0).xyz;
    vec2 material = texelFetch(g_tex2DMaterial, pix, 0).rg;
    vec3 baseColor = texelFetch(g_tex2DBaseColor, pix, 0).rgb;
    vec3 F0 = mix(vec3(0.04), baseColor, material.g);

    vec4 worldPos = mViewProjInv * vec4(vNormalizedXY, 0.5, 1.0);
    point<world, shaded> pixelPos = worldPos.xyz / worldPos.w;
    vec3 viewDir = normalize(pixelPos - cameraPos);

    spectrum<radiance> ibl = iblSpecular(N, viewDir, F0, material.r);
    spectrum<radiance> ssr = texelFetch(g_tex2DSSR, pix, 0).rgb;
    fragColor = vec4(mix(ibl, ssr, 0.5), 1.0);
}
