#version 330 core
#include <safegi/prelude.sgl>
// A shader package's vertex stage builds the tangent frame for normal
// mapping: the bitangent is cross(N, T) scaled by the tangent's handedness
// sign (w), the order the engine's own TBN convention uses.
space object;
space world;
space clip;

uniform rigidmap<object, world> objectToWorld;
uniform projmap<world, clip> viewProj;

in point<object> vertex;
in normal<object> normal;
in vec4 tangent;                  // xyz: the tangent; w: the UV mapping's handedness
out normal<world> worldNormal;
out direction<world> worldTangent;
out direction<world> worldBitangent;

void main() {
    vec4 wpos = objectToWorld * vec4(vertex, 1.0);
    worldNormal = normalize((objectToWorld * vec4(normal, 0.0)).xyz);
    worldTangent = normalize((objectToWorld * vec4(tangent.xyz, 0.0)).xyz);
    worldBitangent = cross(worldNormal, worldTangent) * tangent.w;
    gl_Position = viewProj * wpos;
}
