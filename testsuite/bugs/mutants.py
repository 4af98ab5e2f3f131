#!/usr/bin/env python3
"""Writes the bug catalogue's mutants from each class's correct shader.

Each class folder holds `correct.sgl.<stage>` (checks clean) and the mutants
listed here: one textual change each, so a mutant differs from the correct
shader by exactly one mistake. The escapes are mistakes of the same kind the
language cannot see (right types, wrong value): they check clean, and
measure.py reports them. Run from this folder after editing a correct
shader or this list, then regenerate the .expected files (see CMakeLists.txt)
and review their diffs.
"""
import pathlib
import sys

MUTANTS = {
    "missing_cosine": [  # the paper's first reported bug
        ("point_light_no_cosine", "Kd * lightI * cosTheta * falloff", "Kd * lightI * falloff"),
        ("area_light_no_cosine", "Kd * Le * cosSurface / pdfW", "Kd * Le / pdfW"),
        ("cosine_of_wrong_vectors", "float cosSurface = max(dot(n, wy), 0.0);", "float cosSurface = max(dot(wi, wy), 0.0);"),
    ],
    "light_sampling_normalisation": [  # the paper's second reported bug
        ("divided_by_area_pdf", "Kd * Le * cosSurface / pdfW", "Kd * Le * cosSurface / pdfA"),
        ("no_pdf", "Kd * Le * cosSurface / pdfW", "Kd * Le * cosSurface"),
        ("multiplied_by_pdf", "Kd * Le * cosSurface / pdfW", "Kd * Le * cosSurface * pdfW"),
    ],
    "radiometric_quantities": [
        ("irradiance_as_radiance", "spectrum<radiance> L = Kd * E;", "spectrum<radiance> L = E;"),
        ("radiance_plus_irradiance", "spectrum<radiance> total = L + ambient;", "spectrum<radiance> total = L + E;"),
        ("intensity_as_irradiance", "spectrum<irradiance> E = lightI * cosTheta * falloff;", "spectrum<irradiance> E = lightI * cosTheta;"),
    ],
    "angle_units": [
        ("sine_of_plain_number", "float s = sin(halfAngle);", "float s = sin(0.5);"),
        ("cosine_of_degrees", "float c = cos(halfAngle);", "float c = cos(degrees(halfAngle));"),
        ("angle_compared_with_cosine", "if (cosToAxis > c)", "if (cosToAxis > halfAngle)"),
    ],
    "space_mismatch": [
        ("object_light_world_point", "vector<world, away> toLight = lightPos - P;", "vector<world, away> toLight = lightPosObject - P;"),
        ("direction_away_from_the_light", "vector<world, away> toLight = lightPos - P;", "vector<world, away> toLight = P - lightPos;"),
        ("object_normal_world_direction", "float<proj> cosTheta = max(dot(n, wi), 0.0);", "float<proj> cosTheta = max(dot(nObject, wi), 0.0);"),
        ("object_point_into_world_function", "float<length> d = distanceTo(lightPos, P);", "float<length> d = distanceTo(lightPosObject, P);"),
    ],
    "affine_points": [
        ("point_plus_point", "point<world> mid = P + 0.5 * (lightPos - P);", "point<world> mid = P + lightPos;"),
        ("scaled_point", "vector<world> offset = 0.01 * meter * n;", "vector<world> offset = 0.01 * P;"),
        ("vector_minus_point", "vector<world> toLight = lightPos - P;", "vector<world> toLight = n * meter - P;"),
    ],
    "direction_normalisation": [
        ("vector_as_direction", "direction<world, away> wi = normalize(toLight);", "direction<world, away> wi = toLight;"),
        ("half_vector_not_normalised", "direction<world> h = normalize(wi + wo);", "direction<world> h = wi + wo;"),
        ("reflect_of_a_vector", "direction<world, away> r = reflect(-wi, n);", "direction<world, away> r = reflect(-toLight, n);"),
        ("reflect_of_the_outgoing_direction", "direction<world, away> r = reflect(-wi, n);", "direction<world, away> r = reflect(wi, n);"),
    ],
    "map_misuse": [
        ("map_applied_to_wrong_space", "point<world> P = worldFromObject * position;", "point<world> P = worldFromObject * lightInWorld;"),
        ("maps_that_do_not_meet", "projmap<object, clip> clipFromObject = clipFromWorld * worldFromObject;",
         "projmap<object, clip> clipFromObject = clipFromWorld * objectFromWorld;"),
        ("composition_in_wrong_order", "projmap<object, clip> clipFromObject = clipFromWorld * worldFromObject;",
         "projmap<object, clip> clipFromObject = worldFromObject * clipFromWorld;"),
    ],
    "geometric_kinds": [
        ("vector_transformed_as_normal", "normal<world> n = worldFromObject * normalIn;", "normal<world> n = worldFromObject * tangentIn;"),
        ("normal_used_as_vector", "vector<world> t = worldFromObject * tangentIn;", "vector<world> t = n;"),
        ("hpoint_without_homogenize", "point<clip> ndc = homogenize(clipPos);", "point<clip> ndc = clipPos;"),
    ],
    "shadow_map": [
        ("depth_compared_with_plain_number", "bool lit = depthToLight - bias <= stored;", "bool lit = depthToLight - bias <= 0.5;"),
        ("bias_without_unit", "float<length> bias = 0.05 * meter;", "float<length> bias = 0.05;"),
        ("texel_of_wrong_dimension", "float<length> stored = texture(shadowMap, uv).r;", "float<area> stored = texture(shadowMap, uv).r;"),
    ],
    "roots_and_powers": [
        ("sqrt_of_odd_dimension", "float<length> radius = sqrt(lightArea);", "float<length> radius = sqrt(lightArea * radius0);"),
        ("pow_with_variable_exponent", "float<area> r2 = pow(radius, 2);", "float<area> r2 = pow(radius, shininess);"),
        ("pow_with_fractional_exponent", "float<area> r2 = pow(radius, 2);", "float<area> r2 = pow(radius, 2.5);"),
    ],
    "generic_functions": [
        ("lerp_of_different_dimensions", "float<length> d = lerp(near, far, t);", "float<length> d = lerp(near, exposureTime, t);"),
        ("generic_space_mixup", "float<length> gap = separation(P, lightPos);", "float<length> gap = separation(P, lightPosObject);"),
        ("generic_result_misused", "spectrum<radiance> L = attenuate(Le, visibility);", "spectrum<irradiance> L = attenuate(Le, visibility);"),
    ],
    "units": [
        ("angle_unit_for_length", "float<length> radius = 5.0 * centimeter;", "float<length> radius = 5.0 * degree;"),
        ("length_unit_for_time", "float<time> shutter = 20.0 * millisecond;", "float<time> shutter = 20.0 * millimeter;"),
        ("unit_as_annotation", "float<length> near = 0.1 * meter;", "float<meter> near = 0.1 * meter;"),
    ],
    "camera_transforms": [  # model-view-projection and shadow chains
        ("mvp_in_wrong_order", "clipFromView * viewFromWorld * worldFromObject;", "worldFromObject * viewFromWorld * clipFromView;"),
        ("view_matrix_skipped", "clipFromView * viewFromWorld * worldFromObject;", "clipFromView * worldFromObject;"),
        ("shadow_chain_through_the_camera", "lightClipFromLightView * lightViewFromWorld * worldFromObject;",
         "lightClipFromLightView * viewFromWorld * worldFromObject;"),
    ],
    "points_as_directions": [  # only a difference of points is a vector
        ("light_position_as_direction", "direction<world, away> wi = normalize(toLight);", "direction<world, away> wi = normalize(lightPos);"),
        ("length_of_a_position", "float<length> d = length(toLight);", "float<length> d = length(P);"),
        ("half_vector_from_the_eye_position", "direction<world> h = normalize(wi + wo);", "direction<world> h = normalize(wi + normalize(eyePos));"),
        ("view_direction_reversed", "direction<world, away> wo = normalize(eyePos - P);", "direction<world, away> wo = normalize(P - eyePos);"),
    ],
    "unit_scales": [  # the right dimension in the wrong unit
        ("centimetres_read_as_metres", "float<length> radius = lightRadiusCm in meter;", "float<length> radius = lightRadiusCm;"),
        ("degrees_into_cosine", "cos(coneHalfAngleDeg in radian)", "cos(coneHalfAngleDeg)"),
        ("azimuth_declared_in_degrees", "float<angle> phi = 2.0 * PI * xi.y * radian;", "float<angle in degree> phi = 2.0 * PI * xi.y * radian;"),
    ],
    "perspective_divide": [  # homogeneous coordinates are positions only after the divide by w
        ("screen_uv_without_divide", "vec2 screenUv = hCam.xy / hCam.w * 0.5 + 0.5;", "vec2 screenUv = hCam.xy * 0.5 + 0.5;"),
        ("shadow_ndc_without_divide", "vec3 ndc = hLight.xyz / hLight.w;", "vec3 ndc = hLight.xyz;"),
        ("divided_by_the_other_w", "vec2 screenUv = hCam.xy / hCam.w * 0.5 + 0.5;", "vec2 screenUv = hCam.xy / hLight.w * 0.5 + 0.5;"),
    ],
    "space_conversions": [  # 'in' needs exactly one shortest chain of maps
        ("ambiguous_object_to_world", "point<world> P = worldFromObject * position;", "point<world> P = position in world;"),
        ("normal_through_the_projection", "viewNormal = normalize(n in view);", "viewNormal = normalize(n in clip);"),
        ("light_map_the_other_way", "uniform rigidmap<light, world> worldFromLight;", "uniform rigidmap<world, light> lightFromWorld;"),
    ],
    "microfacet_environment": [  # GGX importance sampling of an environment map
        ("environment_looked_up_by_position", "texture(environment, wi)", "texture(environment, P)"),
        ("no_cosine_of_incidence", "spectrum<radiance> L = fr * Li * cosI / pdfWi;", "spectrum<radiance> L = fr * Li / pdfWi;"),
        ("half_vector_in_tangent_space", "direction<world, away> wi = reflect(-wo, h);", "direction<world, away> wi = reflect(-wo, hT);"),
        ("reflect_of_the_outgoing_direction", "direction<world, away> wi = reflect(-wo, h);", "direction<world, away> wi = reflect(wo, h);"),
    ],
    "pbr_light_arrays": [  # shapes of outside programs (issue #21): LearnOpenGL PBR, a spot light, a normal map
        ("lambert_without_pi", "Lo += (kD * albedo * INV_PI + specular) * E;", "Lo += (kD * albedo + specular) * E;"),
        ("ggx_without_pi", "float<brdf> D = a * a * INV_PI / (denom * denom);", "float<brdf> D = a * a / (denom * denom);"),
        ("blinn_phong_without_pi", "float blinn = (shininess + 8.0) / 8.0 * INV_PI * pow(", "float blinn = (shininess + 8.0) / 8.0 * pow("),
        ("cone_angle_given_its_unit_twice", "float<1> cosInner = cos(radians(innerConeDeg));", "float<1> cosInner = cos(innerConeDeg * degree);"),
        ("reach_left_in_centimetres", "saturateTo(1.0 - ds / reach, 1.0)", "saturateTo(1.0 - ds / spotReachCm, 1.0)"),
        ("half_vector_of_a_light_vector", "direction<world> H = normalize(V + L);", "direction<world> H = normalize(V + toL);"),
        ("vector_for_a_generic_direction", "float<proj> cosL = cosineTo(N, L);", "float<proj> cosL = cosineTo(N, toL);"),
        ("normal_map_left_in_tangent_space", "normal<world> N = normalize(worldFromTangent * nT);", "normal<world> N = normalize(nT);"),
        ("light_vector_reversed", "vector<world, away> toL = lightPositions[i] - WorldPos;", "vector<world, away> toL = WorldPos - lightPositions[i];"),
    ],
    "sampling_and_media": [  # shapes of outside programs (issue #21): light sampling, fog, shadows, TAA
        ("cone_without_steradian", "float<solid_angle> cone = 2.0 * PI * (1.0 - cosMax) * steradian;",
         "float<solid_angle> cone = 2.0 * PI * (1.0 - cosMax);"),
        ("jacobian_without_light_cosine", "1.0 / (areaSize * cosY * invR2)", "1.0 / (areaSize * invR2)"),
        ("phase_without_steradian", "(4.0 * PI * steradian * hg * sqrt(hg))", "(4.0 * PI * hg * sqrt(hg))"),
        ("shadow_depth_before_the_divide", "float currentDepth = ndcL.z * 0.5 + 0.5;", "float currentDepth = hL.z * 0.5 + 0.5;"),
        ("motion_without_the_divide", "motion = hNow.xy / hNow.w - hPrev.xy / hPrev.w;", "motion = hNow.xy - hPrev.xy;"),
    ],
    "glsl_rules": [
        ("undeclared_identifier", "fragColor = vec4(L, 1.0);", "fragColor = vec4(Lo, 1.0);"),
        ("wrong_argument_count", "float<proj> cosTheta = max(dot(n, wi), 0.0);", "float<proj> cosTheta = max(dot(n, wi));"),
        ("assignment_to_uniform", "spectrum<radiance> L = Kd * Le * cosTheta * dw;", "Le = Kd * Le * cosTheta * dw; spectrum<radiance> L = Le;"),
    ],
}


# Mistakes the language cannot see: the types stay right, the value is wrong.
# Each is one textual change like a mutant, written as escape_<name>, and must
# check clean (its .expected is empty); measure.py counts them as not caught.
ESCAPES = {
    "missing_cosine": [
        ("light_cosine_sign", "float cosLight = max(dot(-wy, ny), 0.0);", "float cosLight = max(dot(wy, ny), 0.0);",
         "the sign of a cosine: dot(wy, ny) and dot(-wy, ny) are both proj"),
    ],
    "light_sampling_normalisation": [
        ("pdf_off_by_two", "float<pdf_area> pdfA = 1.0 / lightArea;", "float<pdf_area> pdfA = 2.0 / lightArea;",
         "a constant factor of a pdf (2, π, 1/N): numbers are dimensionless"),
    ],
    "radiometric_quantities": [
        ("extra_pi_in_the_brdf", "spectrum<radiance> L = Kd * E;", "spectrum<radiance> L = Kd * E / 3.14159265;",
         "a factor of π in a BRDF (albedo vs albedo/π): π is dimensionless"),
    ],
    "angle_units": [
        ("full_angle_as_half_angle", "float<angle> halfAngle = 0.5 * spotAngle;", "float<angle> halfAngle = spotAngle;",
         "which angle of the right dimension (the cone's full or half angle)"),
    ],
    "affine_points": [
        ("midpoint_weight", "point<world> mid = P + 0.5 * (lightPos - P);", "point<world> mid = P + 0.25 * (lightPos - P);",
         "the weights of an affine combination"),
    ],
    "direction_normalisation": [
        ("half_vector_of_a_difference", "direction<world> h = normalize(wi + wo);", "direction<world> h = normalize(wi - wo);",
         "which combination of directions is normalized (wi + wo vs wi - wo)"),
    ],
    "geometric_kinds": [
        ("flipped_normal", "normal<world> n = worldFromObject * normalIn;", "normal<world> n = -(worldFromObject * normalIn);",
         "the orientation of a normal, and whether a normal<S> has unit length"),
    ],
    "shadow_map": [
        ("bias_sign", "bool lit = depthToLight - bias <= stored;", "bool lit = depthToLight + bias <= stored;",
         "the sign and size of a bias: both are lengths"),
    ],
    "roots_and_powers": [
        ("area_from_the_wrong_lengths", "float<area> r2 = pow(radius, 2);", "float<area> r2 = radius * radius0;",
         "which quantities of the right dimension are combined (radius² vs radius·radius0)"),
    ],
    "generic_functions": [
        ("lerp_endpoints_swapped", "float<length> d = lerp(near, far, t);", "float<length> d = lerp(far, near, t);",
         "the order of arguments of the same type"),
    ],
    "units": [
        ("wrong_unit_at_a_literal", "float<length> radius = 5.0 * centimeter;", "float<length> radius = 5.0 * millimeter;",
         "the unit written at a number: 5.0 * millimeter is a correct length, just not the intended one"),
    ],
    "unit_scales": [
        ("azimuth_in_degrees", "float<angle> phi = 2.0 * PI * xi.y * radian;", "float<angle> phi = 2.0 * PI * xi.y * degree;",
         "the unit a plain number is given: 2π·ξ * degree is an angle, the checker trusts the unit written"),
    ],
    "perspective_divide": [
        ("uv_without_the_bias", "vec2 shadowUv = ndc.xy * 0.5 + 0.5;", "vec2 shadowUv = ndc.xy * 0.5 - 0.5;",
         "the mapping from NDC to texture coordinates (×0.5 + 0.5, a y flip)"),
    ],
    "space_conversions": [
        ("motion_from_the_current_frame", "motion = P - prevWorldFromObject * position;", "motion = P - worldFromObject * position;",
         "two maps of the same type (this frame's and last frame's model matrix) are interchangeable"),
    ],
    "sampling_and_media": [
        ("phase_angle_reversed", "float<1> cosPhase = dot(wc, -wo);", "float<1> cosPhase = dot(wc, wo);",
         "the orientation of a direction: the phase angle between wc and wo or -wo"),
    ],
    "microfacet_environment": [
        ("pdf_of_the_half_vector", "float<pdf_solid_angle> pdfWi = pdfH / (4.0 * oDotH);", "float<pdf_solid_angle> pdfWi = pdfH;",
         "a dimensionless Jacobian (dωh/dωi = 1/(4 wo·h)): the pdf of h passes for the pdf of wi"),
    ],
}

# What the actual cause of each mutant is, as a phrase its first error (message
# and help) must contain: measure.py counts the mutants whose diagnostic names
# the cause, not just the exponent difference (issue #21). Chosen by reading
# the mutant, not the diagnostic: a phrase the checker does not print is a
# hint to improve, not a phrase to change.
CAUSES = {
    "missing_cosine": {"point_light_no_cosine": "missing cosine", "area_light_no_cosine": "missing cosine",
                       "cosine_of_wrong_vectors": "missing cosine factor, e.g. max(dot(n, wi)"},
    "light_sampling_normalisation": {"divided_by_area_pdf": "a pdf per area where a pdf per solid angle",
                                     "no_pdf": "missing division by a pdf", "multiplied_by_pdf": "multiplied by a pdf where it should divide"},
    "radiometric_quantities": {"irradiance_as_radiance": "irradiance where radiance is expected",
                               "radiance_plus_irradiance": "irradiance where radiance is expected",
                               "intensity_as_irradiance": "missing the inverse-square falloff"},
    "angle_units": {"sine_of_plain_number": "a plain number where an angle is expected",
                    "cosine_of_degrees": "degree where radian is expected", "angle_compared_with_cosine": "its sine or cosine"},
    "space_mismatch": {"object_light_world_point": "missing transform by map<world, object>",
                       "object_normal_world_direction": "missing transform by map<world, object>",
                       "object_point_into_world_function": "missing transform by map<object, world>",
                       "direction_away_from_the_light": "the one away from it is lightPos - P"},
    "affine_points": {"point_plus_point": "subtract them to get a vector", "scaled_point": "a point cannot be scaled",
                      "vector_minus_point": "only point - point and point - vector"},
    "direction_normalisation": {"vector_as_direction": "only through normalize()", "half_vector_not_normalised": "only through normalize()",
                                "reflect_of_a_vector": "only through normalize()",
                                "reflect_of_the_outgoing_direction": "reflect(-wi, n)"},
    "map_misuse": {"map_applied_to_wrong_space": "is already in world, where the map leads",
                   "maps_that_do_not_meet": "its inverse", "composition_in_wrong_order": "apply the projective map last"},
    "geometric_kinds": {"vector_transformed_as_normal": "transform the normal itself", "normal_used_as_vector": "a normal is not a vector",
                        "hpoint_without_homogenize": "divide by w first"},
    "shadow_map": {"depth_compared_with_plain_number": "a plain number where length is expected",
                   "bias_without_unit": "a plain number where length is expected", "texel_of_wrong_dimension": "length where area is expected"},
    "roots_and_powers": {"sqrt_of_odd_dimension": "length^(3/2)", "pow_with_variable_exponent": "constant integer exponent",
                         "pow_with_fractional_exponent": "constant integer exponent"},
    "generic_functions": {"lerp_of_different_dimensions": "a different quantity", "generic_space_mixup": "map<object, world>",
                          "generic_result_misused": "radiance where irradiance is expected"},
    "units": {"angle_unit_for_length": "measures angle, not length", "length_unit_for_time": "measures length, not time",
              "unit_as_annotation": "'meter' is a unit"},
    "camera_transforms": {"mvp_in_wrong_order": "wrong order", "view_matrix_skipped": "must end in view",
                          "shadow_chain_through_the_camera": "must end in light_view"},
    "points_as_directions": {"light_position_as_direction": "normalize(lightPos - p)", "length_of_a_position": "distance(P, p)",
                             "half_vector_from_the_eye_position": "normalize(eyePos - p)",
                             "view_direction_reversed": "the one away from it is normalize(eyePos - P)"},
    "unit_scales": {"centimetres_read_as_metres": "centimeter where meter", "degrees_into_cosine": "degree where radian",
                    "azimuth_declared_in_degrees": "radian where degree"},
    "perspective_divide": {"screen_uv_without_divide": "divide by w", "shadow_ndc_without_divide": "divide by w",
                           "divided_by_the_other_w": "the w of the same homogeneous point"},
    "space_conversions": {"ambiguous_object_to_world": "two maps lead there", "normal_through_the_projection": "a projmap applies only to points",
                          "light_map_the_other_way": "goes the other way"},
    "microfacet_environment": {"environment_looked_up_by_position": "looked up by direction",
                               "no_cosine_of_incidence": "missing cosine", "half_vector_in_tangent_space": "map<tangent, world>",
                               "reflect_of_the_outgoing_direction": "reflect(-wo, h)"},
    "pbr_light_arrays": {"lambert_without_pi": "missing 1/π", "ggx_without_pi": "missing 1/π", "blinn_phong_without_pi": "and 'blinn' are plain numbers",
                         "cone_angle_given_its_unit_twice": "already is angle", "reach_left_in_centimetres": "spotReachCm in meter",
                         "half_vector_of_a_light_vector": "normalize(toL)", "vector_for_a_generic_direction": "only through normalize()",
                         "normal_map_left_in_tangent_space": "missing transform by map<tangent, world>",
                         "light_vector_reversed": "the one away from it is lightPositions[i] - WorldPos"},
    "sampling_and_media": {"cone_without_steradian": "x * steradian", "jacobian_without_light_cosine": "light-side cos",
                           "phase_without_steradian": "x / steradian", "shadow_depth_before_the_divide": "divide by w",
                           "motion_without_the_divide": "divide each by its own w"},
    "glsl_rules": {"undeclared_identifier": "undeclared identifier 'Lo'", "wrong_argument_count": "max(genF<D>, genF<D>)",
                   "assignment_to_uniform": "read-only variable 'Le'"},
}

# What each class cannot express beyond its escapes (docs/typechecker.md, "What the checker catches").
LIMITS = {
    "map_misuse": "the matrix itself: a wrong, transposed or stale matrix uploaded for a map<A, B> has the right type",
    "camera_transforms": "projection parameters (field of view, aspect, near/far, handedness) and the value of a matrix",
    "glsl_rules": "logic GLSL allows (a wrong loop bound, a swapped branch)",
    "microfacet_environment": "projections onto the micro-normal h and onto n share the one proj dimension: wi·h passes for wi·n",
    "space_mismatch": "the orientation of a vector the program leaves unoriented (vector<S> without away or toward)",
    "points_as_directions": "the sign of a direction between two points neither of which is the shaded one (the light's axis)",
    "pbr_light_arrays": "the sign of a direction not anchored at the shaded point: dot(Ls, spotAxis) for dot(-Ls, spotAxis)",
}


def write(root: pathlib.Path, folder: str, name: str, old: str, new: str) -> bool:
    correct = next((root / folder).glob("correct.sgl.*"))
    stage = correct.name.split(".")[-1]
    text = correct.read_text()
    if text.count(old) != 1:
        print(f"{folder}/{name}: '{old}' must occur exactly once in {correct.name}", file=sys.stderr)
        return False
    (root / folder / f"{name}.sgl.{stage}").write_text(text.replace(old, new))
    return True


def main() -> int:
    root = pathlib.Path(__file__).parent
    for folder, mutants in MUTANTS.items():
        for name, old, new in mutants:
            if not write(root, folder, name, old, new):
                return 1
    for folder, escapes in ESCAPES.items():
        for name, old, new, _ in escapes:
            if not write(root, folder, "escape_" + name, old, new):
                return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
