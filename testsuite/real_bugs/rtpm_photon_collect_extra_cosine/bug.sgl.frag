#version 460
#include <safegi/prelude.sgl>
// A progressive photon mapper's collection pass: each photon near the hit
// point contributes BRDF x flux / kernel area. The engine's BSDF evaluation
// returns f times the cosine to the incident direction (what a path tracer
// needs); photons already arrive cosine-distributed, so that cosine is
// divided out again.
space shading : frame;                          // z along the shading normal

struct Photon {
    spectrum<power> flux;
    direction<shading, away> dir;               // toward where the photon came from
};

struct RayData {
    spectrum<radiance> radiance;
};

uniform float<area> kernelArea;                 // pi r^2 of the collection radius
uniform spectrum<brdf> albedoOverPi;
uniform Photon photons[16];
uniform int photonCount;

in direction<shading, away> viewDir;
out vec4 fragColor;

spectrum<brdf * proj> evalBsdfCos(direction<shading, away> wo, direction<shading, away> wi) {
    return albedoOverPi * max(wi.z, 0.0);
}

void main() {
    RayData rayData;
    rayData.radiance = spectrum<radiance>(0.0);
    for (int i = 0; i < photonCount; i++) {
        Photon photon = photons[i];
        float NdotL = photon.dir.z;
        if (NdotL > 0.0) {
            vec3 f_r = evalBsdfCos(viewDir, photon.dir);
            rayData.radiance += (f_r * photon.flux) / kernelArea;
        }
    }
    fragColor = vec4(rayData.radiance, 1.0);
}
