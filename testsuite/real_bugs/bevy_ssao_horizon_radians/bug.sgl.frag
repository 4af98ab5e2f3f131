#version 450
#include <safegi/prelude.sgl>
// A game engine's ambient occlusion with visibility bitmasks: a sample's
// front and back horizon angles (arc cosines, radians) are shifted by the
// slice normal's angle and mapped to [0, 1] to pick the sectors they cover;
// the normal's angle is already divided by pi, so the horizons must be too.
space view : eye;

const float PI = 3.14159265358979;
const float HALF_PI = 1.5707963267949;

layout(location = 0) in point<view> pixelPosition;
layout(location = 1) flat in point<view> samplePosition;
layout(location = 2) flat in float samplingDirection;     // +1 or -1 along the slice
layout(location = 3) flat in float<angle> normalAngle;    // slice normal, from the view vector
layout(location = 4) flat in float<length> thickness;     // assumed depth of a surface
layout(location = 0) out uint occludedBits;

void main() {
    vec3 V = normalize(-pixelPosition);
    vec3 delta = samplePosition - pixelPosition;
    vec3 deltaBack = delta - V * thickness;
    vec2 frontBackHorizon = vec2(acos(dot(normalize(delta), V)), acos(dot(normalize(deltaBack), V)));
    float n = (normalAngle + HALF_PI) / PI;
    vec2 horizons = clamp(samplingDirection * -frontBackHorizon + n, 0.0, 1.0);
    uint startBit = uint(horizons.x * 32.0);
    uint bitCount = uint(ceil((horizons.y - horizons.x) * 32.0));
    occludedBits = bitCount > 0u ? (0xFFFFFFFFu >> (32u - min(bitCount, 32u))) << startBit : 0u;
}
