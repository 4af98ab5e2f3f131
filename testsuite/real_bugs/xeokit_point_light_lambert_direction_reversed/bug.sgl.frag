#version 300 es
#include <safegi/prelude.sgl>
precision highp float;
// A BIM viewer's Lambert shading for a point light, in view space: the
// direction used for the diffuse cosine points from the shaded fragment to
// the light.
space view;

uniform point<view> lightPos;
uniform spectrum<irradiance / proj> lightE;     // on a surface facing the light
uniform spectrum<brdf> diffuseBrdf;
uniform spectrum<radiance> ambient;

in point<view, shaded> vViewPosition;
in normal<view> vViewNormal;
out vec4 fragColor;

void main() {
    normal<view> n = normalize(vViewNormal);
    vector<view, away> toLight = vViewPosition - lightPos;
    direction<view, away> l = normalize(toLight);
    float<proj> lambertian = max(dot(n, l), 0.0);
    spectrum<radiance> L = ambient + diffuseBrdf * lightE * lambertian;
    fragColor = vec4(L, 1.0);
}
