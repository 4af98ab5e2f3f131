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
    default: return EShLangFragment;
  }
}

}  // namespace safegi
