#version 330 core
#include <safegi/prelude.sgl>
// A basic material's environment-map vertex chunk: the reflection is looked
// up in world space, so the normal must reach world space. The normal matrix
// at hand carries it to view space (inverse transpose of the model-view
// matrix); the view matrix is rigid, so multiplying by it from the left (its
// transpose, hence its inverse) brings the view-space normal back to world.
space object;
space world;
space view;
space clip;

uniform map<object, world> modelMatrix;
uniform rigidmap<world, view> viewMatrix;
uniform mat3<object, view, normal> normalMatrix;      // transpose(inverse(mat3(viewMatrix * modelMatrix)))
uniform projmap<view, clip> projectionMatrix;
uniform point<world> cameraPosition;

in point<object> position;
in normal<object> objectNormal;
out direction<world> vReflect;

void main() {
    vec4 worldPosition = modelMatrix * vec4(position, 1.0);
    vec3 transformedNormal = normalMatrix * objectNormal;
    vec3 worldNormal = normalize((vec4(transformedNormal, 0.0) * viewMatrix).xyz);
    vec3 cameraToVertex = normalize(worldPosition.xyz - cameraPosition);
    vReflect = reflect(cameraToVertex, worldNormal);
    gl_Position = projectionMatrix * viewMatrix * worldPosition;
}
