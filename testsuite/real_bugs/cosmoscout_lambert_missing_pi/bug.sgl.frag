#version 330 core
#include <safegi/prelude.sgl>
// A space viewer's planet surface in HDR mode: the sun's illuminance lights a
// Lambertian surface, whose BRDF is the albedo divided by pi (the projected
// solid angle of the hemisphere), so the result is a luminance.
space world;

uniform float<irradiance / proj> uSunIlluminance;      // lux on a surface facing the sun
uniform direction<world> uSunDirection;                // toward the sun
uniform sampler2D<spectrum<1>> uSurfaceTexture;        // albedo

in vec2 vTexCoords;
in normal<world> vNormal;
out vec4 oColor;

const float<projected_solid_angle> PI = float<projected_solid_angle>(3.14159265358979);

void main() {
    vec3 albedo = texture(uSurfaceTexture, vTexCoords).rgb;
    float cosSun = max(dot(normalize(vNormal), uSunDirection), 0.0);
    spectrum<radiance> luminance = albedo * uSunIlluminance * cosSun;
    oColor = vec4(luminance, 1.0);
}
