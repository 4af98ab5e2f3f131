#version 450
#include <safegi/prelude.sgl>
// A Rust WebGPU renderer's forward pass: the interpolated world normal is
// renormalized once, and the lighting context that every light reads (the
// normal, the position and the view direction) is built from that unit
// normal.
space world;

struct LightingGeometricCtx {
    normal<world> worldNormal;
    point<world> position;
    direction<world, away> viewDir;
};

layout(set = 0, binding = 0) uniform Camera {
    point<world> cameraPosition;
};
layout(set = 0, binding = 1) uniform DirectionalLight {
    direction<world, away> lightDir;                 // toward the light
    spectrum<irradiance / proj> lightIlluminance;    // on a surface facing it
};
layout(set = 0, binding = 2) uniform Material {
    spectrum<brdf> diffuse;
};

layout(location = 0) in point<world, shaded> inPosition;
layout(location = 1) in normal<world> inNormal;
layout(location = 0) out vec4 outColor;

spectrum<radiance> shadeDirectional(LightingGeometricCtx ctx) {
    float<proj> nDotL = max(dot(ctx.worldNormal, lightDir), 0.0);
    return diffuse * lightIlluminance * nDotL;
}

void main() {
    vec3 n = normalize(inNormal);
    LightingGeometricCtx ctx = LightingGeometricCtx(n, inPosition, normalize(cameraPosition - inPosition));
    outColor = vec4(shadeDirectional(ctx), 1.0);
}
