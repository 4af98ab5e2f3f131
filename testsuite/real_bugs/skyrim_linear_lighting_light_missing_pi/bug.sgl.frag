#version 450
#include <safegi/prelude.sgl>
// Linear lighting with a physically based diffuse lobe (albedo / pi). The
// game's light colours were authored for a Lambert term without 1/pi: the
// radiance a white Lambertian surface facing the light reflects is the colour
// itself. The irradiance such a light delivers to a surface facing it is
// therefore pi (steradians) times the colour; the fix multiplies it in.
space world;

const float<projected_solid_angle> PI_PSA = float<projected_solid_angle>(3.14159265);

uniform spectrum<radiance> dirLightColor;     // legacy convention (see above)
uniform float directionalLightMult;           // artist multiplier
uniform direction<world> dirLightDir;         // toward the light
uniform spectrum<1> albedo;

in normal<world> vNormal;
out vec4 fragColor;

void main() {
    normal<world> n = normalize(vNormal);
    spectrum<irradiance / proj> lightE = directionalLightMult * dirLightColor;
    float<proj> cosL = max(dot(n, dirLightDir), 0.0);
    spectrum<brdf> diffuse = albedo / PI_PSA;
    spectrum<radiance> L = diffuse * lightE * cosL;
    fragColor = vec4(L, 1.0);
}
