#version 330 core
#include <safegi/prelude.sgl>
// A directional light given by the direction its light travels points toward
// the surface: its cosine with the vertex's own normal is negative where the
// surface is lit, and max(…, 0.0) makes it 0 there. The light's own normal
// (a uniform) belongs to another point: its cosine with that direction is
// positive and not refused.
space view;
uniform direction<view, toward> lightTravel;
uniform normal<view> lightNormal;
uniform spectrum<irradiance / proj> lightColour;
in point<view> P;
in normal<view> N;
out spectrum<irradiance> E;
void main() {
    vec3 n = normalize(N);
    float lit = max(dot(n, -lightTravel), 0.0) * max(dot(lightNormal, lightTravel), 0.0);
    float dark = clamp(dot(lightTravel, n), 0.0, 1.0);
    E = lightColour * (lit + dark);
    gl_Position = vec4(P, 1.0);
}
