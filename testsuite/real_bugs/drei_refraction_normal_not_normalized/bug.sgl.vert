#version 300 es
#include <safegi/prelude.sgl>
// A three.js add-on's ray-traced refraction material, vertex stage: the world
// normal for refract() and the Fresnel term of the fragment stage (which uses
// it as interpolated) is the view-space normal carried back to world space by
// the inverse view matrix. The normal matrix may scale it, so it is normalized
// before it leaves the stage.
precision highp float;
space object;
space world;
space view;
space clip;

uniform map<object, world> modelMatrix;
uniform rigidmap<world, view> viewMatrix;
uniform mat3<object, view, normal> normalMatrix;
uniform projmap<view, clip> projectionMatrix;
uniform point<world> cameraPosition;

out point<world> vWorldPosition;
out normal<world> vNormal;
out direction<world> viewDirection;

in point<object> position;
in normal<object> normal;

void main() {
    vec4 transformedNormal = vec4(normal, 0.0);
    vec4 transformedPosition = vec4(position, 1.0);
    mat4 viewMatrixInv = inverse(viewMatrix);
    vWorldPosition = (modelMatrix * transformedPosition).xyz;
    vNormal = (viewMatrixInv * vec4(normalMatrix * transformedNormal.xyz, 0.0)).xyz;
    viewDirection = normalize(vWorldPosition - cameraPosition);
    gl_Position = projectionMatrix * viewMatrix * modelMatrix * transformedPosition;
}
