#version 330 core
#include <safegi/prelude.sgl>
// A fixed-function-style vertex shader with an environment map: the
// reflection is computed in view space, where the camera sits at the origin,
// so the incident ray is the normalised view-space position and reflect()
// takes it as it is (GLSL's I points toward the surface).
space object;
space view : eye;                                // the camera at the origin
space clip;

uniform map<object, view> worldView;
uniform mat3<object, view, normal> normalMatrix;
uniform projmap<view, clip> projection;

in point<object, shaded> position;
in normal<object> normalIn;
out direction<view> viewSpaceReflection;

void main() {
    vec3 viewPosition = (worldView * vec4(position, 1.0)).xyz;
    vec3 viewNormal = normalize(normalMatrix * normalIn);
    vec3 incidentView = normalize(viewPosition);
    viewSpaceReflection = reflect(incidentView, viewNormal);
    gl_Position = projection * vec4(viewPosition, 1.0);
}
