#version 330 core
#include <safegi/prelude.sgl>
// A software rasterizer's Gouraud path, as a vertex shader: a point light's
// direction and distance are measured from the vertex's world position, the
// one the model transformation (translation, rotation) produced.
space object;
space world;
space clip;

uniform map<object, world> modelMatrix;
uniform projmap<world, clip> viewProjection;
uniform point<world> lightPosition;
uniform spectrum<intensity> lightIntensity;
uniform spectrum<brdf> diffuseOverPi;

in point<object> position;
in normal<object> normalIn;
out spectrum<radiance> shadedColor;

void main() {
    point<world> worldPos = (modelMatrix * vec4(position, 1.0)).xyz;
    normal<world> N = normalize(vec4(normalIn, 0.0) * inverse(modelMatrix)).xyz;
    vec3 toLight = lightPosition - worldPos;
    float d = length(toLight);
    float cosTheta = max(dot(N, toLight / d), 0.0);
    shadedColor = diffuseOverPi * lightIntensity * inverse_square(d) * cosTheta;
    gl_Position = viewProjection * vec4(worldPos, 1.0);
}
