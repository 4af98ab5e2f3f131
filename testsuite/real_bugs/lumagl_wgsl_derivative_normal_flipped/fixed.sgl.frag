#version 450
#include <safegi/prelude.sgl>
// A WebGL/WebGPU shader library's PBR material, WebGPU path rewritten as GLSL:
// without vertex normals the geometric normal is rebuilt from screen-space
// derivatives of the world position. WebGPU's framebuffer y axis points down,
// against WebGL's, so the y derivative is reversed and the cross product that
// gives the outward normal in WebGL gives the inward one there; the fix swaps
// its operands.
space world;

uniform point<world> u_camera;
uniform point<world> u_lightPosition;
uniform vec3 u_lightColor;
uniform vec3 u_baseColor;

layout(location = 0) in point<world, shaded> pbr_vPosition;
layout(location = 0) out vec4 fragColor;

void main() {
    vec3 pos_dx = dFdx(pbr_vPosition);
    vec3 pos_dy = dFdy(pbr_vPosition);
    vec3 n = normalize(cross(pos_dy, pos_dx));
    vec3 l = normalize(u_lightPosition - pbr_vPosition);
    vec3 v = normalize(u_camera - pbr_vPosition);
    vec3 h = normalize(l + v);
    float NdotL = clamp(dot(n, l), 0.001, 1.0);
    float NdotH = clamp(dot(n, h), 0.0, 1.0);
    vec3 color = u_lightColor * (u_baseColor * NdotL + vec3(pow(NdotH, 32.0)));
    fragColor = vec4(color, 1.0);
}
