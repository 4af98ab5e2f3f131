// Choosing one of a mix material's two materials at a hit.
//
// pbrt-v3's MixMaterial sums the two BSDFs, the first weighted by `amount`
// and the second by 1 − amount. Summing would need every pair of lobes in
// one BSDF (and a specular one beside a glossy one); instead each hit picks
// one material with probability p = amount's channel mean, as pbrt-v4's
// MixMaterial does, and weighs what it scatters by amount / p (or (1 − amount)
// / (1 − p)): the expected weighted BSDF is pbrt-v3's sum, and a grey amount
// weighs by exactly 1. The pick is a hash of the hit and the incoming
// direction, not a sampler dimension, so scenes without mixes draw the same
// samples as before.
#pragma once

#include "accel/geometry.hpp"
#include "safegi/cpu_renderer/scene.hpp"
#include "textures/surface_texture.hpp"

namespace safegi::render {

struct MaterialChoice {
  const Material* material = nullptr;  // null: black (absorbs)
  Reflectance weight{1.0f};            // what the chosen BSDF's light is multiplied by
  bool weighted = false;               // weight is not 1 (a coloured amount)
};

// The material `index` stands for at `hit` (mixes resolved, nested ones too),
// reached by a ray along `footprint.direction`; the amounts' textures
// filtered over `footprint`, as the diffuse reflectance is.
MaterialChoice choose_material(const Scene& scene, const SurfaceTextures& textures, int index, const SurfaceHit& hit,
                               const ConeFootprint& footprint, Time time);

// Whether any material `index` may stand for is not specular (where caustic
// photons land).
bool scatters_non_specularly(const Scene& scene, int index);

// A number in [0, 1) that only the hit and the incoming direction decide.
Real mix_choice_number(PointWorld position, DirectionWorld incoming, int material);

}  // namespace safegi::render
