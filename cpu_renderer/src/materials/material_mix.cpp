#include "materials/material_mix.hpp"

#include <bit>
#include <cstdint>

#include "integrators/sampler.hpp"

namespace safegi::render {

Real mix_choice_number(PointWorld position, DirectionWorld incoming, int material) {
  uint32_t h = static_cast<uint32_t>(material);
  const sg::vec3_rep p = sg::raw(position), d = sg::raw(incoming);
  for (int c = 0; c < 3; ++c) {
    h = sampling_detail::hash_combine(h, std::bit_cast<uint32_t>(static_cast<float>(p[c])));
    h = sampling_detail::hash_combine(h, std::bit_cast<uint32_t>(static_cast<float>(d[c])));
  }
  return sampling_detail::to_unit_float(h);
}

bool scatters_non_specularly(const Scene& scene, int index) {
  if (index < 0) return false;
  const Material& material = scene.materials[index];
  if (!material.mix) return !is_specular(material.model);
  return scatters_non_specularly(scene, material.mix->first) || scatters_non_specularly(scene, material.mix->second);
}

MaterialChoice choose_material(const Scene& scene, const SurfaceTextures& textures, int index, const SurfaceHit& hit,
                               const ConeFootprint& footprint, Time time) {
  const DirectionWorld incoming = footprint.direction;
  MaterialChoice choice;
  // A mix names materials made before it, so the chain ends; the bound only
  // guards a malformed Scene built by hand.
  for (int depth = 0; index >= 0 && depth < 64; ++depth) {
    const Material& material = scene.materials[index];
    if (!material.mix) {
      choice.material = &material;
      return choice;
    }
    const MaterialMix& mix = *material.mix;
    // A weight: a texture above 1 is clamped (the importer warns).
    const sg::vec3_rep channels = glm::min(sg::raw(textures.reflectance_at(mix.amount, hit, footprint, time)), sg::vec3_rep(1));
    const Reflectance amount = sg::from_raw<Reflectance>(channels);
    const Real p = sg::average(amount);
    const bool grey = channels.r == channels.g && channels.g == channels.b;
    if (mix_choice_number(hit.position, incoming, index) < p) {
      index = mix.first;
      if (!grey) choice.weight = choice.weight * (amount / p);
    } else {
      index = mix.second;
      if (!grey) choice.weight = choice.weight * ((Reflectance(1.0f) - amount) / (1 - p));
    }
    choice.weighted = choice.weighted || !grey;
  }
  return choice;
}

}  // namespace safegi::render
