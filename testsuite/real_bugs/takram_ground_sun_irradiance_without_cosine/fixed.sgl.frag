#version 300 es
#include <safegi/prelude.sgl>
// Volumetric clouds over a physical atmosphere (a three.js add-on): light the
// ground below a cloud sample bounces up into it. The ground receives the sky's
// irradiance and the sun's; the sun's is the solar irradiance at normal
// incidence (attenuated by the atmosphere) times the cosine between the ground
// normal and the sun, and the ground reflects both as a Lambertian surface. A
// cloud particle, which has no surface, takes sunlight without a cosine.
precision highp float;
space world;

uniform spectrum<irradiance / proj> solarIrradiance;   // on a plane facing the sun
uniform spectrum<1> transmittanceToSun;
uniform spectrum<irradiance> skyIrradiance;             // on the ground plane
uniform direction<world> sunDirection;                  // toward the sun
uniform normal<world> groundNormal;
uniform float<1> coverage;
uniform spectrum<1> cloudAlbedo;
uniform float<1> groundTransmittance;                   // exp(-optical depth to the ground)

const float RECIPROCAL_PI = 0.3183098861837907;
const float RECIPROCAL_PI2 = 0.15915494309189535;
const float RECIPROCAL_PI4 = 0.07957747154594767;

out vec4 fragColor;

spectrum<irradiance / proj> sunIrradianceForParticle() {
    return solarIrradiance * transmittanceToSun;
}

spectrum<irradiance> sunIrradianceOnSurface(normal<world> n) {
    return solarIrradiance * transmittanceToSun * max(dot(n, sunDirection), 0.0);
}

void main() {
    vec3 sunIrradiance = sunIrradianceOnSurface(groundNormal);
    vec3 groundIrradiance = skyIrradiance + (1.0 - coverage) * sunIrradiance;
    const float groundAlbedo = 0.3;
    spectrum<radiance> groundRadiance = groundAlbedo * RECIPROCAL_PI * groundIrradiance;
    // isotropic phase function, 1 / (4 pi) per steradian
    spectrum<radiance> sunScattering = cloudAlbedo * RECIPROCAL_PI4 * sunIrradianceForParticle();
    // the ground fills the lower hemisphere: half of the isotropic phase's weight
    spectrum<radiance> bounced = 0.5 * cloudAlbedo * groundRadiance * groundTransmittance;
    fragColor = vec4(sunScattering + bounced, 1.0);
}
