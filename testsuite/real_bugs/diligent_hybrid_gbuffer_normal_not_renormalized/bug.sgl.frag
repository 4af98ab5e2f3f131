#version 460
#include <safegi/prelude.sgl>
// A hybrid renderer's screen pass (a compute shader in the original): the
// world normal read back from a half-float G-buffer is renormalized before
// it offsets the shadow and reflection rays, enters N.L and mirrors the view
// ray; the background is told apart by a near-zero normal.
space world;
space clip;

uniform sampler2D<normal<world>> g_GBuffer_Normal;    // RGBA16F, written normalized
uniform sampler2D g_GBuffer_Depth;
uniform projmap<clip, world> ViewProjInv;
uniform point<world> CameraPos;
uniform direction<world, away> LightDir;               // toward the sun
uniform spectrum<irradiance / proj> SunIrradiance;
uniform spectrum<brdf> Albedo;
uniform float<1> SMALL_OFFSET;
uniform vec2 Dim;
out vec4 outColor;

float<1> traceVisibility(point<world> origin, direction<world> dir) {
    return 1.0;   // the inline ray query of the original, elided
}

void main() {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    vec3 WNormal = texelFetch(g_GBuffer_Normal, pix, 0).xyz;
    if (dot(WNormal, WNormal) < 0.01) {
        outColor = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }

    float depth = texelFetch(g_GBuffer_Depth, pix, 0).x;
    vec4 h = ViewProjInv * vec4(gl_FragCoord.xy / Dim * 2.0 - 1.0, depth, 1.0);
    point<world, shaded> WPos = h.xyz / h.w;

    vec3 ViewRayDir = WPos - CameraPos;
    float DisToCamera = length(ViewRayDir);
    ViewRayDir /= DisToCamera;
    float NdotL = max(0.0, dot(LightDir, WNormal));
    point<world> origin = WPos + WNormal * SMALL_OFFSET * DisToCamera;
    NdotL *= traceVisibility(origin, LightDir);
    direction<world> reflDir = reflect(ViewRayDir, WNormal);
    float<1> reflVisible = traceVisibility(origin, reflDir);

    spectrum<radiance> direct = Albedo * SunIrradiance * NdotL;
    outColor = vec4(direct * (0.5 + 0.5 * reflVisible), 1.0);
}
