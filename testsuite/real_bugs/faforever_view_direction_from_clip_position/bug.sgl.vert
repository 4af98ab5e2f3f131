#version 330 core
#include <safegi/prelude.sgl>
// A real-time-strategy game's community patch, unit vertex shader: the view
// direction for specular lighting is taken from the camera to the vertex's
// world position; the output position is the clip-space one. (The fix
// computes the view direction before the position variable is reused for the
// clip-space position.)
space object;
space world;
space clip;

uniform map<object, world> worldMatrix;
uniform projmap<world, clip> viewProjMatrix;
uniform point<world> cameraPosition;

in point<object> position;
out vec3 viewDirection;

void main() {
    vec4 worldPos = worldMatrix * vec4(position, 1.0);
    vec4 clipPos = viewProjMatrix * worldPos;
    viewDirection = normalize(clipPos.xyz - cameraPosition);
    gl_Position = clipPos;
}
