// The GLM types behind points, vectors, spectra and maps, in the representation
// config.hpp chooses (safegi::real: float, or double with SAFEGI_DOUBLE=1).
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "safegi/typed/config.hpp"

namespace safegi {
inline namespace SAFEGI_MODE_NAMESPACE {
using vec3_rep = glm::vec<3, real>;
using vec4_rep = glm::vec<4, real>;
using mat3_rep = glm::mat<3, 3, real>;
using mat4_rep = glm::mat<4, 4, real>;
}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi
