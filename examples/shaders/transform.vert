#version 330 core
// Hand-written twin of transform.sgl.vert.

uniform mat4 worldFromObject;
uniform mat4 clipFromWorld;

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 objectNormal;

out vec3 P;
out vec3 N;

void main() {
    P = (worldFromObject * vec4(position, 1.0)).xyz;
    N = normalize(transpose(inverse(mat3(worldFromObject))) * objectNormal);
    gl_Position = clipFromWorld * vec4(P, 1.0);
}
