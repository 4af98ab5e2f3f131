#version 330 core
#include <safegi/prelude.sgl>
// A WPF 3D toolkit's perspective camera (its Direct3D back end): the camera's
// FieldOfView property is in degrees, while the projection (built like
// PerspectiveFovLH) wants the angle in radians; the y scale is cot(fov / 2).
space object;
space view;

uniform float<angle in degree> fieldOfView;   // the camera property, as the user sets it
uniform float aspectRatio;
uniform float<length> nearPlane;
uniform float<length> farPlane;
uniform map<object, view> modelView;

in point<object> position;

void main() {
    vec3 p = (modelView * vec4(position, 1.0)).xyz;
    float yScale = 1.0 / tan(fieldOfView * 0.5);
    float xScale = yScale / aspectRatio;
    float zScale = farPlane / (farPlane - nearPlane);
    gl_Position = vec4(p.x * xScale, p.y * yScale, (p.z - nearPlane) * zScale, p.z);
}
