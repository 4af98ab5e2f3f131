#!/usr/bin/env python3
"""Writes the bug catalogue's mutants from each class's correct shader.

Each class folder holds `correct.sgl.<stage>` (checks clean) and the mutants
listed here: one textual change each, so a mutant differs from the correct
shader by exactly one mistake. Run from this folder after editing a correct
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
        ("object_light_world_point", "vector<world> toLight = lightPos - P;", "vector<world> toLight = lightPosObject - P;"),
        ("object_normal_world_direction", "float<proj> cosTheta = max(dot(n, wi), 0.0);", "float<proj> cosTheta = max(dot(nObject, wi), 0.0);"),
        ("object_point_into_world_function", "float<length> d = distanceTo(lightPos, P);", "float<length> d = distanceTo(lightPosObject, P);"),
    ],
    "affine_points": [
        ("point_plus_point", "point<world> mid = P + 0.5 * (lightPos - P);", "point<world> mid = P + lightPos;"),
        ("scaled_point", "vector<world> offset = 0.01 * meter * n;", "vector<world> offset = 0.01 * P;"),
        ("vector_minus_point", "vector<world> toLight = lightPos - P;", "vector<world> toLight = n * meter - P;"),
    ],
    "direction_normalisation": [
        ("vector_as_direction", "direction<world> wi = normalize(toLight);", "direction<world> wi = toLight;"),
        ("half_vector_not_normalised", "direction<world> h = normalize(wi + wo);", "direction<world> h = wi + wo;"),
        ("reflect_of_a_vector", "direction<world> r = reflect(-wi, n);", "direction<world> r = reflect(-toLight, n);"),
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
    "glsl_rules": [
        ("undeclared_identifier", "fragColor = vec4(L, 1.0);", "fragColor = vec4(Lo, 1.0);"),
        ("wrong_argument_count", "float<proj> cosTheta = max(dot(n, wi), 0.0);", "float<proj> cosTheta = max(dot(n, wi));"),
        ("assignment_to_uniform", "spectrum<radiance> L = Kd * Le * cosTheta * dw;", "Le = Kd * Le * cosTheta * dw; spectrum<radiance> L = Le;"),
    ],
}


def main() -> int:
    root = pathlib.Path(__file__).parent
    for folder, mutants in MUTANTS.items():
        correct = next((root / folder).glob("correct.sgl.*"))
        stage = correct.name.split(".")[-1]
        text = correct.read_text()
        for name, old, new in mutants:
            if text.count(old) != 1:
                print(f"{folder}/{name}: '{old}' must occur exactly once in {correct.name}", file=sys.stderr)
                return 1
            (root / folder / f"{name}.sgl.{stage}").write_text(text.replace(old, new))
    return 0


if __name__ == "__main__":
    sys.exit(main())
