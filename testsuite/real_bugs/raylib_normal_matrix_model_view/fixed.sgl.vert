#version 330 core
#include <safegi/prelude.sgl>
// A game library's basic-lighting vertex shader: the fragment shader lights
// in world space (light positions and the eye are world points), so the
// normal goes to world space too, by the normal matrix of the model matrix
// alone; the view matrix belongs to the projection chain only.
space object;
space world;
space view;
space clip;

uniform map<object, world> matModel;
uniform map<world, view> matView;
uniform projmap<view, clip> matProjection;

in point<object> vertexPosition;
in normal<object> vertexNormal;
out point<world> fragPosition;
out normal<world> fragNormal;

void main() {
    mat3 matNormal = transpose(inverse(mat3(matModel)));
    fragPosition = vec3(matModel * vec4(vertexPosition, 1.0));
    fragNormal = normalize(matNormal * vertexNormal);
    gl_Position = matProjection * matView * matModel * vec4(vertexPosition, 1.0);
}
