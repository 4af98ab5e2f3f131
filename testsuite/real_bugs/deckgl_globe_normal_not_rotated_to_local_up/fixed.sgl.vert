#version 300 es
#include <safegi/prelude.sgl>
// A map renderer's 3D layer in globe mode: a layer gives its normals in the
// local frame of each vertex (east, north, up); on the globe, whose common
// space is centred on the earth, they are rotated so that the local up is the
// direction from the centre to the vertex.
precision highp float;
space enu;
space common;
space clip;

uniform projmap<common, clip> viewProjectionMatrix;
uniform direction<common> polarAxis;

in point<common> positionCommon;
in normal<enu> normals;
out normal<common> vNormal;

void main() {
    vec3 up = normalize(vector<common>(positionCommon));
    vec3 east = normalize(cross(polarAxis, up));
    vec3 north = cross(up, east);
    mat3<enu, common, rigid> localToCommon = mat3(east, north, up);
    vNormal = localToCommon * normals;
    gl_Position = viewProjectionMatrix * vec4(positionCommon, 1.0);
}
