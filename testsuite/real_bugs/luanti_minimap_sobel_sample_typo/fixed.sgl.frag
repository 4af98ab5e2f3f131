#version 330 core
#include <safegi/prelude.sgl>
// A voxel game's minimap shading: the terrain height map is differentiated
// with a Sobel filter over the eight neighbours of each texel, the gradient
// becomes a bump normal in the map's frame, and the map is lit by a fixed
// light and the player's yaw direction.
space minimap;

uniform sampler2D baseTexture;
uniform sampler2D normalTexture;          // heights in .r
uniform direction<minimap> yawVec;

in vec4 varColor;
in vec2 varTexCoord;
out vec4 fragColor;

void main() {
    vec2 uv = varTexCoord.st;
    const float step = 1.0 / 256.0;
    float tl = texture(normalTexture, vec2(uv.x - step, uv.y + step)).r;
    float t  = texture(normalTexture, vec2(uv.x,        uv.y + step)).r;
    float tr = texture(normalTexture, vec2(uv.x + step, uv.y + step)).r;
    float r  = texture(normalTexture, vec2(uv.x + step, uv.y       )).r;
    float br = texture(normalTexture, vec2(uv.x + step, uv.y - step)).r;
    float b  = texture(normalTexture, vec2(uv.x,        uv.y - step)).r;
    float bl = texture(normalTexture, vec2(uv.x - step, uv.y - step)).r;
    float l  = texture(normalTexture, vec2(uv.x - step, uv.y       )).r;
    float dX = (tr + 2.0 * r + br) - (tl + 2.0 * l + bl);
    float dY = (bl + 2.0 * b + br) - (tl + 2.0 * t + tr);
    normal<minimap> bump = normal<minimap>(normalize(vec3(dX, dY, 0.1)));
    float height = 2.0 * texture(normalTexture, uv).r - 1.0;
    vec4 base = texture(baseTexture, uv);
    vec3 L = normalize(vec3(0.0, 0.75, 1.0));
    float specular = pow(clamp(dot(reflect(L, bump), yawVec), 0.0, 1.0), 1.0);
    float diffuse = dot(yawVec, bump);
    vec3 color = (1.1 * diffuse + 0.05 * height + 0.5 * specular) * base.rgb;
    fragColor = vec4(color * varColor.rgb, base.a);
}
