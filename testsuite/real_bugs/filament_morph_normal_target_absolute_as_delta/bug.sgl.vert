#version 300 es
#include <safegi/prelude.sgl>
// A real-time engine's morph targets: positions are stored as displacements,
// but each target's normal, extracted from its tangent frame, is an absolute
// normal; the blend therefore adds each target's difference from the base
// normal, weighted, and renormalizes.
precision highp float;
space object;
space clip;

uniform projmap<object, clip> clipFromObject;
uniform vec2 morphWeights;

in point<object> basePosition;
in normal<object> baseNormal;
in vector<object> positionDelta0;
in vector<object> positionDelta1;
in normal<object> targetNormal0;                   // absolute, not a displacement
in normal<object> targetNormal1;
out normal<object> vNormal;

void main() {
    point<object> p = basePosition + morphWeights.x * positionDelta0 + morphWeights.y * positionDelta1;
    vec3 n = baseNormal;
    n += morphWeights.x * targetNormal0;
    n += morphWeights.y * targetNormal1;
    vNormal = normalize(n);
    gl_Position = clipFromObject * vec4(p, 1.0);
}
