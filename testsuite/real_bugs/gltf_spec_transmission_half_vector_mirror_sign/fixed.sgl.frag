#version 450
#include <safegi/prelude.sgl>
// KHR_materials_transmission's implementation note, written out: light that
// arrives from below a thin transmissive surface is treated like a reflection
// by mirroring the light direction through the surface plane to the viewer's
// side, L + 2 (N . -L) N, and taking the usual half vector with the view
// direction. The light direction points from the surface toward the light,
// which lies below the surface, so N . -L is the positive cosine.
space world;

uniform direction<world> lightDir;                 // toward the light (below)
uniform spectrum<irradiance / proj> lightE;        // on a surface facing the light
uniform spectrum<1> transmissionTint;
uniform float alphaRoughness;
uniform point<world> cameraPos;

in point<world, shaded> vPosition;
in normal<world> vNormal;
out vec4 fragColor;

void main() {
    normal<world> n = normalize(vNormal);
    direction<world, away> v = normalize(cameraPos - vPosition);
    vec3 lMirror = lightDir + 2.0 * dot(n, -lightDir) * n;
    direction<world> hT = normalize(v + lMirror);
    float<proj> NdotH = max(dot(n, hT), 0.0);
    float<proj> NdotL = max(dot(n, -lightDir), 0.0);
    float a2 = alphaRoughness * alphaRoughness;
    float d = NdotH * NdotH * (a2 - 1.0) + 1.0;
    float D = a2 / (3.14159265 * d * d);
    spectrum<radiance> L = transmissionTint * float<brdf>(D * 0.25) * lightE * NdotL;
    fragColor = vec4(L, 1.0);
}
