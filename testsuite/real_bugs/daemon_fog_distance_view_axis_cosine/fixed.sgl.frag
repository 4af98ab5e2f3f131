#version 330 core
#include <safegi/prelude.sgl>
// An id-tech-derived engine's fog: the fog a fragment receives grows with the
// length of the eye ray that reaches it through the fog, so the distance is
// measured along that ray, from the eye to the point, and not along the
// camera's view axis (which shortens it by the cosine of the angle between the
// axis and the ray, so fog thins toward the screen's edges).
space world;

uniform point<world> u_ViewOrigin;
uniform direction<world> u_ViewForward;
uniform float<inv_length> u_FogDensity;
uniform vec4 u_FogColor;

in point<world> var_Position;
out vec4 outputColor;

void main() {
    vector<world> toPoint = var_Position - u_ViewOrigin;
    float dist = length(toPoint);
    float fogAmount = 1.0 - exp(-u_FogDensity * dist);
    outputColor = vec4(u_FogColor.rgb, fogAmount);
}
