#version 330 core
#include <safegi/prelude.sgl>
// A deferred light volume pass of a C++ game engine: the pixel's position is
// reconstructed from linear depth along the camera's far-plane ray (a vector
// from the camera), and only then moved to world space by adding the camera
// position. The eye vector for the specular term is the reversed ray, taken
// before that move.
space world;

uniform point<world> cCameraPosPS;
uniform point<world> cLightPosPS;
uniform vec4 cLightColor;
uniform sampler2D sAlbedoBuffer;
uniform sampler2D sNormalBuffer;
uniform sampler2D sDepthBuffer;

in vector<world> vFarRay;
in vec4 vScreenPos;
out vec4 fragColor;

float GetSpecular(vec3 normal, vector<world> eyeVec, direction<world> lightDir, float specularPower) {
    vec3 halfVec = normalize(normalize(eyeVec) + lightDir);
    return pow(max(dot(normal, halfVec), 0.0), specularPower);
}

void main() {
    vec2 uv = vScreenPos.xy / vScreenPos.w;
    float depth = texture(sDepthBuffer, uv).r;
    vec3 worldPos = vFarRay * depth;
    vec4 normalInput = texture(sNormalBuffer, uv);
    vec4 albedoInput = texture(sAlbedoBuffer, uv);

    // Position acquired via the far ray is relative to the camera: bring it to world space
    vec3 eyeVec = -worldPos;
    worldPos += cCameraPosPS;

    vec3 normal = normalize(normalInput.rgb * 2.0 - 1.0);
    direction<world> lightDir = normalize(cLightPosPS - worldPos);
    float diff = max(dot(normal, lightDir), 0.0);
    float spec = GetSpecular(normal, eyeVec, lightDir, normalInput.a * 255.0);
    fragColor = diff * vec4(cLightColor.rgb * (albedoInput.rgb + spec * cLightColor.a * albedoInput.aaa), 0.0);
}
