#version 330 core
#include <safegi/prelude.sgl>
// A game engine's robotics extension imports a robot description's camera
// sensor: the description gives the horizontal field of view in radians,
// while the engine's camera sensor component keeps its field of view in
// degrees, so the importer converts before storing it. The sensor's
// projection then goes back to radians for the tangent.
space view;
space clip;

uniform float<angle> sdfHorizontalFov;          // from the robot description (radians)
uniform float<1> aspect;
uniform float<length> nearPlane;
uniform float<length> farPlane;

in point<view> position;

vec4 projectSensor(float<angle in degree> fovDeg, point<view> p) {
    float f = 1.0 / tan(radians(fovDeg) * 0.5);
    float z = (farPlane + nearPlane) / (nearPlane - farPlane) * p.z
            + 2.0 * farPlane * nearPlane / (nearPlane - farPlane);
    return vec4(f / aspect * p.x, f * p.y, z, -p.z);
}

void main() {
    float sensorFovDeg = degrees(sdfHorizontalFov);
    gl_Position = projectSensor(sensorFovDeg, position);
}
