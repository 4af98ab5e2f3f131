#version 330 core
#include <safegi/prelude.sgl>
// A scientific-visualisation raycaster: front-to-back compositing with opacity
// correction a' = 1 - (1 - a)^(step / reference step). Entry and exit points
// come in texture coordinates [0, 1]^3; the step is a physical length, so they
// are carried to the volume's model space by its basis before their distance
// is taken, and a volume with a non-uniform basis looks the same from every
// side.
space tex_s;
space model_s;

uniform sampler3D volume;
uniform sampler1D transferFunction;
uniform map<tex_s, model_s> textureToModel;      // the volume's basis and offset
uniform float<length> referenceSamplingInterval;
uniform int samples;

in point<tex_s> entryPoint;
in point<tex_s> exitPoint;
out vec4 fragColor;

void main() {
    vec3 entryModel = (textureToModel * vec4(entryPoint, 1.0)).xyz;
    vec3 exitModel = (textureToModel * vec4(exitPoint, 1.0)).xyz;
    float rayLength = distance(entryPoint, exitPoint);
    float tIncr = rayLength / float(samples);
    vec4 result = vec4(0.0);
    for (int i = 0; i < samples; ++i) {
        vec3 p = mix(entryPoint, exitPoint, (float(i) + 0.5) / float(samples));
        vec4 c = texture(transferFunction, texture(volume, p).r);
        c.a = 1.0 - pow(1.0 - c.a, tIncr / referenceSamplingInterval);
        result.rgb += (1.0 - result.a) * c.a * c.rgb;
        result.a += (1.0 - result.a) * c.a;
    }
    fragColor = result;
}
