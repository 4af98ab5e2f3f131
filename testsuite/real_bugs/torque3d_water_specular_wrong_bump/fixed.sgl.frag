#version 330 core
#include <safegi/prelude.sgl>
// A water surface's sun glint: the bump normal from the ripple maps is
// exaggerated sideways (its xy scaled up) for a livelier highlight, and the
// exaggerated normal, renormalised, is the one the Blinn lobe uses.
space world;

uniform sampler2D bumpMap;
uniform direction<world> lightVec;                    // the sun's travel direction
uniform spectrum<radiance> sunColor;
uniform float specularPower;

in vec2 rippleUV;
in direction<world> eyeVec;                           // from the surface to the eye
out vec4 fragColor;

void main() {
    vec3 bumpNorm = normalize(texture(bumpMap, rippleUV).rgb * 2.0 - 1.0);
    vec3 newbump = bumpNorm;
    newbump.xy *= 3.5;
    newbump = normalize(newbump);
    vec3 halfAng = normalize(eyeVec + -lightVec);
    float specular = pow(clamp(dot(newbump, halfAng), 0.0, 1.0), specularPower);
    spectrum<radiance> glint = sunColor * specular;
    fragColor = vec4(glint, 1.0);
}
