#version 330 core
#include <safegi/prelude.sgl>
// A creative-coding library's image-based lighting: the diffuse light is read
// from an equirectangular (world-direction) map at the surface normal. The
// normals reach the fragment stage in camera space, so the camera's rotation
// is undone (camera-to-world) before the lookup; otherwise orbiting the
// camera drags the environment's lighting along.
space world;
space view;

uniform mat3<view, world, rigid> uCameraRotation;   // camera-to-world rotation
uniform sampler2D environmentMapDiffused;
uniform spectrum<brdf> uAlbedo;

in normal<view> vNormal;
out vec4 fragColor;

vec2 mapTextureToNormal(direction<world> v) {
    float u = atan(v.z, v.x) / (2.0 * 3.14159265) + 0.5;
    float w = acos(clamp(v.y, -1.0, 1.0)) / 3.14159265;
    return vec2(u, w);
}

void main() {
    vec3 n = normalize(vNormal);
    vec3 worldNormal = uCameraRotation * n;
    vec2 uv = mapTextureToNormal(n);
    vec3 irradiance = texture(environmentMapDiffused, uv).rgb;
    fragColor = vec4(uAlbedo * irradiance, 1.0);
}
