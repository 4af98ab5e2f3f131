#pragma once
// glslang's name for a stage: shared by the SPIR-V library and the test
// helper (testing/glslang_check.cpp), both of which hand GLSL to glslang.
#include <glslang/Public/ShaderLang.h>

#include <safegi/typechecker/checker.hpp>

namespace safegi {

inline EShLanguage glslang_language(Stage stage) {
  switch (stage) {
    case Stage::vertex: return EShLangVertex;
    case Stage::tess_control: return EShLangTessControl;
    case Stage::tess_evaluation: return EShLangTessEvaluation;
    case Stage::geometry: return EShLangGeometry;
    case Stage::compute: return EShLangCompute;
    case Stage::task: return EShLangTask;
    case Stage::mesh: return EShLangMesh;
    case Stage::ray_generation: return EShLangRayGen;
    case Stage::intersection: return EShLangIntersect;
    case Stage::any_hit: return EShLangAnyHit;
    case Stage::closest_hit: return EShLangClosestHit;
    case Stage::miss: return EShLangMiss;
    case Stage::callable: return EShLangCallable;
    default: return EShLangFragment;
  }
}

}  // namespace safegi
