#version 330 core
#include <safegi/prelude.sgl>
// Vertex stage of a basic normal-map shader: world-space tangent and normal
// for the fragment stage's tangent frame; the tangent's w holds its handedness.
space object;
space world;
space clip;

uniform map<object, world> _Object2World;
uniform projmap<object, clip> _MVP;

in point<object> vertex;
in normal<object> aNormal;
in vec4 tangent;
out vec3 tangentWorld;
out normal<world> normalWorld;

void main() {
    normalWorld = normalize(vec4(aNormal, 0.0) * inverse(_Object2World)).xyz;
    tangentWorld = normalize((_Object2World * tangent).xyz);
    gl_Position = _MVP * vec4(vertex, 1.0);
}
