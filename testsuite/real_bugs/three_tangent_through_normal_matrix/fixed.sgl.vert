#version 330 core
#include <safegi/prelude.sgl>
// A web engine's vertex normal chunk with tangents: the normal goes through
// the normal matrix (inverse transpose), the tangent lies in the surface and
// goes through the model-view matrix like any direction.
space object;
space view;
space clip;

uniform map<object, view> modelViewMatrix;
uniform mat3<object, view, normal> normalMatrix;     // transpose(inverse(mat3(modelViewMatrix)))
uniform projmap<view, clip> projectionMatrix;

in point<object> position;
in normal<object> objectNormal;
in direction<object> objectTangent;
out normal<view> vNormal;
out direction<view> vTangent;

void main() {
    vec3 transformedNormal = normalMatrix * objectNormal;
    vec3 transformedTangent = (modelViewMatrix * vec4(objectTangent, 0.0)).xyz;
    vNormal = normalize(transformedNormal);
    vTangent = normalize(transformedTangent);
    vec4 mvPosition = modelViewMatrix * vec4(position, 1.0);
    gl_Position = projectionMatrix * mvPosition;
}
