#version 330 core
#include <safegi/prelude.sgl>
// A kart game's object pass, vertex stage: the normal goes to view space by the
// inverse transpose of the model-view matrix (it keeps orthogonality to the
// surface), the tangent and bitangent by the model-view matrix itself (they
// are directions along the surface and keep them).
space object;
space world;
space view : eye;
space clip;

uniform map<object, world> ModelMatrix;
uniform map<world, object> InverseModelMatrix;
uniform rigidmap<world, view> ViewMatrix;
uniform rigidmap<view, world> InverseViewMatrix;
uniform projmap<view, clip> ProjectionMatrix;

in point<object> Position;
in normal<object> Normal;
in direction<object> Tangent;
in direction<object> Bitangent;
out normal<view> nor;
out vector<view, 1> tangent;
out vector<view, 1> bitangent;

void main() {
    mat4 TransposeInverseModelView = transpose(InverseModelMatrix * InverseViewMatrix);
    gl_Position = ProjectionMatrix * ViewMatrix * ModelMatrix * vec4(Position, 1.0);
    nor = (TransposeInverseModelView * vec4(Normal, 0.0)).xyz;
    tangent = (ViewMatrix * ModelMatrix * vec4(Tangent, 0.0)).xyz;
    bitangent = (ViewMatrix * ModelMatrix * vec4(Bitangent, 0.0)).xyz;
}
