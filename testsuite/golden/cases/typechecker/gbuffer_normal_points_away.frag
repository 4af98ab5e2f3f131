#version 330 core
#include <safegi/prelude.sgl>
// A normal read from a G-buffer is the shaded pixel's own normal: it points away
// from its surface, so its cosine with a light's travel direction is negative
// where the light falls. Bounded at 0 that cosine is 0 there; its acos is the
// angle to the other side, π − θ (a slope-scaled shadow bias).
space view : eye;
uniform sampler2D<normal<view>> normals;
uniform direction<view, toward> lightTravel;
in vec2 uv;
out vec4 c;
void main() {
    vec3 n = normalize(texture(normals, uv).xyz);
    float<proj> lit = max(dot(n, -lightTravel), 0.0);
    float slope = tan(acos(dot(n, -lightTravel)));
    float wrongSlope = tan(acos(dot(n, lightTravel)));
    float<proj> dark = max(dot(n, lightTravel), 0.0);
    c = vec4(lit, slope, wrongSlope, dark);
}
