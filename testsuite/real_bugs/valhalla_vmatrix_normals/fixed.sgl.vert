#version 330 core
#include <safegi/prelude.sgl>
// A Cube-engine derivative lets a map author transform a texture slot's
// geometry with an arbitrary matrix (/vmatrix, which may scale unevenly):
// positions take the matrix, normals its inverse transpose.
space object;
space world;
space clip;

uniform map<object, world> vmatrix;
uniform projmap<world, clip> camprojmatrix;

in point<object> vvertex;
in normal<object> vnormal;
out normal<world> nvec;

void main() {
    vec4 wpos = vmatrix * vec4(vvertex, 1.0);
    mat3 nmatrix = transpose(inverse(mat3(vmatrix)));
    nvec = normalize(nmatrix * vnormal);
    gl_Position = camprojmatrix * wpos;
}
