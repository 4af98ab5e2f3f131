#version 400
#include <safegi/prelude.sgl>
// A material-graph generator's Gooch (cool-to-warm) shading example, as its
// GLSL code evaluates it: the light term mixes a cool and a warm colour by the
// cosine between the normal and the light, and the highlight compares the
// reflected light with the view direction. The view direction is read in
// world space, so the graph reads the normal in world space too.
space object;
space world;

uniform point<world> u_viewPosition;
uniform direction<world, away> u_lightDirection;     // toward the light
uniform vec3 coolColor;
uniform vec3 warmColor;
uniform vec3 surfaceColor;
uniform float<1> alpha;
uniform float<1> beta;

in point<world, shaded> positionWorld;
in normal<world> normalWorld;
in normal<object> normalObject;
out vec4 out1;

void main() {
    vec3 N = normalize(normalWorld);
    vec3 V = normalize(u_viewPosition - positionWorld);
    float NdotL = dot(N, u_lightDirection);
    float t = (1.0 + NdotL) * 0.5;
    vec3 kCool = coolColor + alpha * surfaceColor;
    vec3 kWarm = warmColor + beta * surfaceColor;
    vec3 gooch = mix(kCool, kWarm, t);
    vec3 R = reflect(-u_lightDirection, N);
    float s = pow(max(dot(R, V), 0.0), 32.0);
    out1 = vec4(gooch + vec3(s), 1.0);
}
