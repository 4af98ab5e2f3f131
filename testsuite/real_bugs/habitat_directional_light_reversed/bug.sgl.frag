#version 330 core
#include <safegi/prelude.sgl>
// An embodied-AI simulator's Phong shader, directional lights: a scene gives a
// directional light by the direction its light travels; the shading needs the
// direction toward the light, so that vector is reversed before it is used
// (the simulator reverses it when it fills the uniform; written here in the
// shader).
space world;

uniform direction<world, toward> lightTravelDir;   // as the scene specifies it
uniform vec3 lightColor;
uniform vec3 diffuseColor;
uniform vec3 specularColor;
uniform float shininess;
uniform point<world> cameraPos;

in point<world, shaded> worldPos;
in normal<world> vNormal;
out vec4 fragColor;

void main() {
    vec3 n = normalize(vNormal);
    vec3 toLight = lightTravelDir;
    vec3 toCamera = normalize(cameraPos - worldPos);
    float nDotL = max(dot(n, toLight), 0.0);
    vec3 r = reflect(-toLight, n);
    float spec = pow(max(dot(r, toCamera), 0.0), shininess);
    fragColor = vec4(lightColor * (diffuseColor * nDotL + specularColor * spec), 1.0);
}
