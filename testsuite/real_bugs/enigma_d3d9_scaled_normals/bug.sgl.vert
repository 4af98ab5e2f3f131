#version 330 core
#include <safegi/prelude.sgl>
// A game-maker runtime's per-vertex lighting: users scale models freely with
// transform calls, so the normal carried by the world matrix's normal matrix
// is no longer of unit length and is normalised before the light's cosine
// (what GL_NORMALIZE did on the GL backend).
space object;
space world;
space clip;

uniform map<object, world> worldMatrix;
uniform projmap<world, clip> viewProjMatrix;
uniform direction<world> lightDir;           // toward the light
uniform vec3 lightColor;
uniform vec3 ambientColor;

in point<object> inPosition;
in normal<object> inNormal;
out vec3 vColor;

void main() {
    vec3 N = transpose(inverse(mat3(worldMatrix))) * inNormal;
    float lambert = max(dot(N, lightDir), 0.0);
    vColor = ambientColor + lightColor * lambert;
    gl_Position = viewProjMatrix * worldMatrix * vec4(inPosition, 1.0);
}
