#version 300 es
precision highp float;
#include <safegi/prelude.sgl>
// A WebGL library's linear fog: the fog factor is a function of how far the
// fragment is in front of the camera, the view-space depth -mvPosition.z that
// the vertex stage passes down as a varying.
uniform vec3 fogColor;
uniform float<length> fogNear;
uniform float<length> fogFar;
uniform vec4 diffuseColor;

in float<length> vFogDepth;      // -mvPosition.z
out vec4 fragColor;

void main() {
    vec4 color = diffuseColor;
    float depth = gl_FragCoord.z / gl_FragCoord.w;
    float fogFactor = smoothstep(fogNear, fogFar, depth);
    fragColor = vec4(mix(color.rgb, fogColor, fogFactor), color.a);
}
