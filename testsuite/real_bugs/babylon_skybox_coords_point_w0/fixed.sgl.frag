#version 330 core
#include <safegi/prelude.sgl>
// A skybox material: the cube map is looked up with the fragment's world
// position carried into the reflection texture's frame by the reflection
// matrix. That matrix may translate (a skybox centred on the camera), so the
// position must enter it with w = 1.
space world;
space cube;

uniform map<world, cube> reflectionMatrix;
uniform samplerCube<spectrum<radiance>> reflectionSampler;
uniform float<1> reflectionLevel;

in point<world> vPositionW;
out vec4 fragColor;

vec3 computeSkyBoxCoords(point<world> positionW, map<world, cube> m) {
    return vec3(m * vec4(positionW, 1.0));
}

void main() {
    vec3 coords = computeSkyBoxCoords(vPositionW, reflectionMatrix);
    spectrum<radiance> color = texture(reflectionSampler, coords).rgb * reflectionLevel;
    fragColor = vec4(color, 1.0);
}
