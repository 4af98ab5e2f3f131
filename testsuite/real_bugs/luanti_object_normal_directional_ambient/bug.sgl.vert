#version 330 core
#include <safegi/prelude.sgl>
// Voxel game's entity vertex shader: a directional ambient term weights the
// squared world-axis components of the normal (brighter facing up, darker
// facing down), so it takes the normal in world space, after the entity's
// transform (which may scale: entities have a visual size per axis).
space object;
space world;
space clip;

uniform map<object, world> mWorld;
uniform projmap<object, clip> mWorldViewProj;

in point<object> inVertexPosition;
in normal<object> inVertexNormal;
out normal<world> vNormal;
out float vIDiff;

float directional_ambient(normal<world> n) {
    vec3 v = n * n;
    if (n.y < 0.0)
        return dot(v, vec3(0.670820, 0.447213, 0.836660));
    return dot(v, vec3(0.670820, 1.000000, 0.836660));
}

void main() {
    gl_Position = mWorldViewProj * vec4(inVertexPosition, 1.0);
    vNormal = (mWorld * vec4(inVertexNormal, 0.0)).xyz;
    vIDiff = length(inVertexNormal) == 0.0
        ? 1.0
        : directional_ambient(normalize(inVertexNormal));
}
