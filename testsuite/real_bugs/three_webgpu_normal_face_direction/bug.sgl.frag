#version 330 core
#include <safegi/prelude.sgl>
// A web 3D library's new renderer builds the shading normal of a double-sided
// material: on a back face the interpolated vertex normal points away from
// the viewer, so it is multiplied by the face direction (+1 front, -1 back)
// before the directional light's diffuse term.
space view : eye;

uniform direction<view, away> lightDirection;    // toward the light
uniform spectrum<irradiance / proj> lightColor;
uniform spectrum<brdf> diffuseColor;

in normal<view> vNormal;
out vec4 fragColor;

void main() {
    float faceDirection = gl_FrontFacing ? 1.0 : -1.0;
    vec3 normal = normalize(vNormal);
    float dotNL = max(dot(normal, lightDirection), 0.0);
    spectrum<radiance> L = diffuseColor * lightColor * dotNL;
    fragColor = vec4(L, 1.0);
}
