#version 450
#include <safegi/prelude.sgl>
// Projected snow and moss: the material's projection axis is a row of the
// per-draw texture-projection matrix, expressed in the mesh's object space.
// The pixel shader compares it with world-space normals to decide where the
// snow lies, so the vertex shader carries the axis to world space with the
// linear part of the object's world transform.
space object;
space world;
space clip;

uniform map<object, world> World;
uniform projmap<world, clip> ViewProj;
uniform direction<object> texProjAxis;      // projection axis, object space

in point<object> aPosition;
out point<world> vWorldPosition;
out direction<world> vTexProj;             // compared with world normals

void main() {
    vec4 worldPos = World * vec4(aPosition, 1.0);
    vWorldPosition = worldPos.xyz;
    vTexProj = texProjAxis;
    gl_Position = ViewProj * worldPos;
}
