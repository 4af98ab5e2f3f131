#version 300 es
#include <safegi/prelude.sgl>
// A globe renderer's clipping planes for a tileset: each plane is given in the
// tileset's frame and moved to eye coordinates for the test; its normal goes
// through the normal matrix of the plane transform (the inverse transpose), a
// point of it through the transform itself.
precision highp float;
space tileset;
space eye : eye;

uniform map<tileset, eye> clippingPlanesMatrix;
uniform mat3<tileset, eye, normal> normalClippingPlanesMatrix;
uniform normal<tileset> planeNormal;
uniform point<tileset> planePoint;

in point<eye> v_positionEC;
out vec4 fragColor;

void main() {
    normal<eye> n = normalize((clippingPlanesMatrix * vec4(planeNormal, 0.0)).xyz);
    vec4 pointEC = clippingPlanesMatrix * vec4(planePoint, 1.0);
    float signedDistance = dot(v_positionEC - pointEC.xyz, n);
    if (signedDistance < 0.0) {
        discard;
    }
    fragColor = vec4(1.0);
}
