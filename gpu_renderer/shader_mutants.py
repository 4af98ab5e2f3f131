#!/usr/bin/env python3
"""The mistakes path tracers are known for, made in this path tracer's own
shaders: each mutant changes one expression of gpu_renderer/shaders and
safeglslc must refuse the result with the named diagnostic (and accept the
unchanged shaders). docs/gpu-renderer.md lists them with the ones the checker
cannot see.

Usage: shader_mutants.py SAFEGLSLC SHADER_DIR
"""
import pathlib
import shutil
import subprocess
import sys
import tempfile

# (file, what is written, the mistake, the diagnostic code expected)
MUTANTS = [
    ("integrator.sgl", "throughput * f * wi.z * light.radianceOverPdf", "throughput * f * light.radianceOverPdf",
     "E-DIMENSION-MISMATCH"),  # forgotten cosine at the shading point
    ("lights.sgl", "intensity * inverse_square(chosen.distance) / choice", "intensity / choice",
     "E-DIMENSION-MISMATCH"),  # point light without the inverse-square law
    ("lights.sgl", "chosen.pdf = choice * solidAngleDensity(1.0 / area, chosen.distance, cosLight);",
     "chosen.pdf = choice / area;", "E-DIMENSION-MISMATCH"),  # area density used as solid-angle density
    ("lights.sgl", "return pdfArea / (cosLight * inverse_square(distance));", "return pdfArea * cosLight / (distance * distance);",
     "E-DIMENSION-MISMATCH"),  # the Jacobian inverted: cos / d² where d² / cos belongs (d² / cos written out is right)
    ("lights.sgl", "vector<world, away> toLight = lightPosition[light] - shaded;",
     "vector<world, away> toLight = shaded - lightPosition[light];", "E-ORIENTATION"),  # reversed light vector
    ("material_lambert.sgl", "return albedo / HEMISPHERE_PROJECTED;", "return albedo;",
     "E-DIMENSION-MISMATCH"),  # Lambert without its 1/π
    ("material_phong.sgl", "/ HEMISPHERE_SOLID_ANGLE;", "/ (2.0 * HEMISPHERE_PROJECTED);",
     "E-DIMENSION-MISMATCH"),  # lobe density per projected solid angle where per solid angle is due
    ("integrator.sgl", "ray = spawnRay(surface, shadingToWorld * scattered.wi);", "ray = spawnRay(surface, scattered.wi);",
     "E-SPACE-MISMATCH"),  # a shading-frame direction traced as a world one
    ("integrator.sgl", "direction<shading> wi = worldToShading * light.wi;",
     "direction<shading> wi = shadingToWorld * light.wi;", "E-SPACE-MISMATCH"),  # the frame applied backwards
    ("lights.sgl", "chosen.radianceOverPdf = environmentRadianceTowards(sky.wi) / chosen.pdf;",
     "chosen.radianceOverPdf = environmentRadianceTowards(sky.wi) * chosen.pdf;", "E-DIMENSION-MISMATCH"),  # times the pdf
    ("integrator.sgl", "radiance += throughput * environmentRadianceTowards(ray.direction) * weight;",
     "radiance += throughput * environmentRadianceTowards(ray.direction) * weight / previousPdf;", "E-DIMENSION-MISMATCH"),
    ("material_plastic.sgl", "specular * fresnelDielectric(dot(wi, h), eta) * torranceSparrow(alpha, wo, wi, h);",
     "specular * fresnelDielectric(dot(wi, h), eta) * torranceSparrow(alpha, wo, wi, h) * wi.z;",
     "E-DIMENSION-MISMATCH"),  # the cosine folded into the BRDF
    ("microfacet.sgl", "return trowbridgeReitzDensity(alpha, h) * max(h.z, 0.0) / (4.0 * abs(dot(wo, h)));",
     "return trowbridgeReitzDensity(alpha, h) / (4.0 * abs(dot(wo, h)));", "E-DIMENSION-MISMATCH"),  # D not made a density of normals
    ("lights.sgl", "return 4.0 * PI * r * r;", "return 4.0 * PI * r;", "E-DIMENSION-MISMATCH"),  # a sphere's area
    ("surface.sgl", "return Ray(surface.position + surface.normal * offset, direction);",
     "return Ray(surface.position + offset, direction);", "E-KIND-MISMATCH"),  # offset added to every coordinate
    ("lights.sgl", "return lightChoiceProbability(light) * solidAngleDensity(1.0 / area, distance(origin, surface.position), cosLight);",
     "return lightChoiceProbability(light);", "E-DIMENSION-MISMATCH"),  # the light's choice probability taken for its density (MIS)
    ("lights.sgl", "return lightChoiceProbability(frame.environmentLight) * environmentDirectionPdf(wi);",
     "return lightChoiceProbability(frame.environmentLight) * SPHERE_SOLID_ANGLE;", "E-DIMENSION-MISMATCH"),  # the sky's density inverted (times 4π sr)
    ("environment.sgl", "return SkySample(worldFromSky() * w, mapDensity / solidAnglePerMapArea(sinTheta));",
     "return SkySample(worldFromSky() * w, mapDensity);", "E-DIMENSION-MISMATCH"),  # the map's density without the sin θ Jacobian
    ("environment.sgl", "return environmentMapDensity(p.uv) / solidAnglePerMapArea(p.sinTheta);",
     "return environmentMapDensity(p.uv) * solidAnglePerMapArea(p.sinTheta);", "E-DIMENSION-MISMATCH"),  # the Jacobian inverted
    ("environment.sgl", "return 2.0 * PI * PI * sinTheta * steradian;", "return 2.0 * PI * PI * sinTheta;",
     "E-DIMENSION-MISMATCH"),  # the map's area stretch as a number
    ("environment.sgl", "direction<sky> w = transpose(worldFromSky()) * wi;", "direction<sky> w = worldFromSky() * wi;",
     "E-SPACE-MISMATCH"),  # the sky's rotation applied backwards
    ("environment.sgl", "return SkySample(worldFromSky() * w,", "return SkySample(w,", "E-SPACE-MISMATCH"),  # a sky-frame direction used as a world one
    ("surface.sgl", "float<1> b1 = determinant > 0.0 ? (d22 * d1 - d12 * d2) / determinant : 0.0;",
     "float<1> b1 = determinant > 0.0 ? (d22 * d1 - d12 * d2) / d11 : 0.0;", "E-DIMENSION-MISMATCH"),  # a barycentric weight not normalised
    ("lights.sgl", "return 1.0 / (HEMISPHERE_SOLID_ANGLE * oneMinusCos);", "return 1.0 / oneMinusCos;",
     "E-DIMENSION-MISMATCH"),  # the cone's density as a plain number (its 2π sr left out)
]


def compile_shaders(safeglslc, folder):
    return subprocess.run([safeglslc, "--target-env", "vulkan1.2", "--strict", "--Werror", str(folder / "path_tracer.comp"), "-o", "-"],
                          capture_output=True, text=True)


def main():
    safeglslc, shaders = sys.argv[1], pathlib.Path(sys.argv[2])
    failures = 0
    clean = compile_shaders(safeglslc, shaders)
    if clean.returncode != 0:
        print("the unchanged shaders do not compile:\n" + clean.stderr)
        return 1
    for file, written, mistake, code in MUTANTS:
        with tempfile.TemporaryDirectory() as tmp:
            copy = pathlib.Path(tmp) / "shaders"
            shutil.copytree(shaders, copy)
            text = (copy / file).read_text()
            if text.count(written) != 1:
                print(f"FAIL {file}: '{written}' is not in the shader exactly once (the mutant is stale)")
                failures += 1
                continue
            (copy / file).write_text(text.replace(written, mistake))
            result = compile_shaders(safeglslc, copy)
            caught = result.returncode != 0 and f"[{code}]" in result.stderr
            print(f"{'ok  ' if caught else 'FAIL'} {file}: {mistake}  ->  {code if caught else 'not refused as ' + code}")
            if not caught:
                print(result.stderr[:2000])
                failures += 1
    print(f"{len(MUTANTS) - failures} of {len(MUTANTS)} mutants refused")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
