#version 450
#include <safegi/prelude.sgl>
// A voxel game's light-shaft (god-ray) pass, vertex stage of the full-screen
// quad: the sun's position, far along the sun direction, is projected to the
// screen so that the fragment stage can blur radially from it. The math
// library hands the view-projection matrix over in the transposed layout.
space world;

uniform mat4 viewProjectionStored;      // world-to-clip, stored transposed
uniform direction<world> sunDirection;  // toward the sun
uniform float<length> sunDistance;

in vec2 quadPos;
out vec2 sunScreen;
out vec2 texCoord;

void main() {
    vec3 sunPosition = sunDirection * sunDistance;
    vec4 sunClip = transpose(viewProjectionStored) * vec4(sunPosition, 1.0);
    sunScreen = sunClip.xy / sunClip.w * 0.5 + 0.5;
    texCoord = quadPos * 0.5 + 0.5;
    gl_Position = vec4(quadPos, 0.0, 1.0);
}
