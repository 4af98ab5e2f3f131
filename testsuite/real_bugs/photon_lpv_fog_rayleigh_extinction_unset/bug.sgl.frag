#version 330 core
#include <safegi/prelude.sgl>
// A shader pack's light-propagation-volume fog: scattering and extinction
// coefficients at a point are the Rayleigh and Mie coefficients weighted by
// the two densities. Rayleigh scattering absorbs nothing, so its extinction
// coefficient is its scattering coefficient; the separate Rayleigh extinction
// field of the parameter block is never filled in.
struct OverworldFogParameters {
    spectrum<inv_length> rayleigh_scattering_coeff;
    spectrum<inv_length> rayleigh_extinction_coeff;   // never set
    spectrum<inv_length> mie_scattering_coeff;
    spectrum<inv_length> mie_extinction_coeff;
};

uniform spectrum<inv_length> rayleighScattering;
uniform spectrum<inv_length> mieScattering;
uniform spectrum<inv_length> mieExtinction;

in vec2 density;                          // x: Rayleigh, y: Mie (plain multipliers)
in float<length> stepLength;
out vec4 fragColor;

void main() {
    OverworldFogParameters fog_params;
    fog_params.rayleigh_scattering_coeff = rayleighScattering;
    fog_params.mie_scattering_coeff = mieScattering;
    fog_params.mie_extinction_coeff = mieExtinction;

    spectrum<inv_length> scattering = fog_params.rayleigh_scattering_coeff * density.x
        + fog_params.mie_scattering_coeff * density.y;
    spectrum<inv_length> extinction = fog_params.rayleigh_extinction_coeff * density.x
        + fog_params.mie_extinction_coeff * density.y;
    vec3 transmittance = exp(-extinction * stepLength);
    fragColor = vec4(scattering * stepLength * transmittance, 1.0);
}
