#version 450
#include <safegi/prelude.sgl>
// A double-sided material turns the interpolated normal toward the viewer by
// the face direction, +1 or -1: a unit vector times a sign is still unit, so
// the flipped normal still gives a cosine. Any other factor scales it into a
// vector, whose dot product is no cosine.
space view : eye;

uniform direction<view, away> toLight;
uniform spectrum<irradiance / proj> lightColor;
uniform spectrum<brdf> albedo;
uniform float<1> bend;

in normal<view> vNormal;
out vec4 color;

void main() {
    float faceDirection = gl_FrontFacing ? 1.0 : -1.0;
    vec3 n = normalize(vNormal) * faceDirection;
    spectrum<radiance> lit = albedo * lightColor * max(dot(n, toLight), 0.0);
    vec3 bent = normalize(vNormal) * bend;
    spectrum<radiance> wrong = albedo * lightColor * max(dot(bent, toLight), 0.0);
    color = vec4(lit + wrong, 1.0);
}
