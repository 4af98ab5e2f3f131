#version 450
#include <safegi/prelude.sgl>
// Flattening a scene's instanced triangle meshes into world space (here as a
// vertex shader over the shape's vertices): positions go through the
// instance transform, shading normals through its inverse transpose, since a
// pbrt scene may scale a shape non-uniformly.
space object;
space world;

uniform map<object, world> xfm;

layout(location = 0) in point<object> P;
layout(location = 1) in normal<object> N;
layout(location = 0) out point<world> worldP;
layout(location = 1) out normal<world> worldN;

void main() {
    worldP = (xfm * vec4(P, 1.0)).xyz;
    worldN = normalize((transpose(inverse(xfm)) * vec4(N, 0.0)).xyz);
    gl_Position = vec4(0.0);
}
