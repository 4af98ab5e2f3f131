#version 450
#include <safegi/prelude.sgl>
// A volume raycaster's front-to-back compositing. The transfer function's
// opacity a is defined for a standard step (half a voxel); a step of another
// length s transmits (1 - a)^(s / standard step), so the opacity correction's
// exponent is a ratio of two lengths.
space world;
space volume_uvw;

uniform sampler3D volumeTex;
uniform sampler1D transferFunction;
uniform map<world, volume_uvw> worldToTexture;
uniform float<length> standardStepSize;        // half a voxel, world units
uniform int numSteps;

in point<world> vEntry;
in point<world> vExit;
out vec4 fragColor;

float adjustOpacity(float<1> a, float<1> relativeStepLength) {
    return 1.0 - pow(1.0 - a, relativeStepLength);
}

void main() {
    vec4 v = vec4(0.0);
    point<world> wprev = vEntry;
    for (int i = 1; i <= numSteps; ++i) {
        point<world> wpos = mix(vEntry, vExit, float(i) / float(numSteps));
        vec3 uvw = (worldToTexture * vec4(wpos, 1.0)).xyz;
        vec4 x = texture(transferFunction, texture(volumeTex, uvw).r);
        float adjusted_alpha = adjustOpacity(x.a, distance(wpos, wprev) / standardStepSize);
        v.rgb = v.rgb + (1.0 - v.a) * x.rgb * adjusted_alpha;
        v.a = v.a + (1.0 - v.a) * adjusted_alpha;
        wprev = wpos;
        if (v.a >= 1.0) {
            break;
        }
    }
    fragColor = v;
}
