#version 330 core
#include <safegi/prelude.sgl>
// A voxel game's object (entity) vertex shader: the directional ambient term
// weights the squared components of the normal by fixed per-axis factors of
// the world (up brighter than down), so the normal it reads must be the one
// in world space, carried there by the object's world matrix.
space object;
space world;
space clip;

uniform map<object, world> mWorld;
uniform projmap<object, clip> mWorldViewProj;

in point<object> inVertexPosition;
in normal<object> inVertexNormal;

out normal<world> vNormal;
out point<world> worldPosition;
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
    worldPosition = (mWorld * vec4(inVertexPosition, 1.0)).xyz;
    vIDiff = length(vNormal) == 0.0
        ? 1.0
        : directional_ambient(normalize(vNormal));
}
