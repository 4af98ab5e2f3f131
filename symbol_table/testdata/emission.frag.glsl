#version 330 core
                             
                                     
// Interpolated and uniform emission plus an environment lookup, exposed and tinted.
in vec3               Lv;
uniform vec3               Le;
uniform float exposure;
uniform vec3        tint[2];
uniform sampler2D                     environment;
uniform mat4               cameraFromWorld;
layout(std140) uniform Camera { mat4               viewFromWorld; float         focalLength; } camera;
layout(location = 0) out vec3               color;
void main() {
  color = (Lv + Le + texture(environment, vec2(0.5)).rgb) * exposure * tint[0] * tint[1];
}
