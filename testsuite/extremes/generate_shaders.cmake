# Writes the generated extreme shaders into OUT_DIR (called at configure time
# by CMakeLists.txt, and by bench/extremes/run.py with larger sizes):
#   derived_chain_N       dimension d_i = d_{i-1} * length, i = 1..N: exponents beyond
#                         the literal limit of 1000, reached through names
#   generic_chain_N       N generic functions, each calling the previous one
#   operator_chain_N      x * x / x ... with N operator pairs, one per line
#   swizzle_chain_N       v.xyzw.xyzw ... with N swizzles, one per line
#   nested_parens_N       N nested parentheses around x
# Inputs: OUT_DIR, SIZES (a list of KIND=N, e.g. derived_chain=2000).
set(_header "#version 330 core\n#include <safegi/prelude.sgl>\n")

function(_write kind n body)
  file(WRITE ${OUT_DIR}/${kind}_${n}.sgl.frag "${_header}${body}")
endfunction()

# Lines 1..n of `pattern`, with <i> replaced by the line's number and <p> by the previous one.
function(_numbered_lines out n pattern)
  set(lines "")
  foreach(i RANGE 1 ${n})
    math(EXPR previous "${i} - 1")
    string(REPLACE "<i>" "${i}" line "${pattern}")
    string(REPLACE "<p>" "${previous}" line "${line}")
    string(APPEND lines "${line}\n")
  endforeach()
  set(${out} "${lines}" PARENT_SCOPE)
endfunction()

function(derived_chain n)
  _numbered_lines(links ${n} "dimension d<i> = d<p> * length;")
  set(body "dimension d0 = length;\n${links}")
  math(EXPR exponent "${n} + 1")
  math(EXPR thousands "${exponent} / 1000")
  math(EXPR rest "${exponent} % 1000")
  set(spelled "length^${rest}")
  if(thousands GREATER 0)
    foreach(i RANGE 1 ${thousands})
      string(APPEND spelled " * length^1000")
    endforeach()
  endif()
  string(APPEND body "out vec4 fragColor;\nvoid main() {\n    float<d${n}> x = float<d${n}>(1.0);\n"
                     "    float<${spelled}> y = x;\n    fragColor = vec4(y / float<d${n}>(1.0));\n}\n")
  _write(derived_chain ${n} "${body}")
endfunction()

function(generic_chain n)
  _numbered_lines(calls ${n} "template<dimension D> float<D> f<i>(float<D> x) { return f<p>(x); }")
  set(body "template<dimension D> float<D> f0(float<D> x) { return x; }\n${calls}")
  string(APPEND body "out vec4 fragColor;\nvoid main() {\n    float<radiance> y = f${n}(float<radiance>(1.0));\n"
                     "    fragColor = vec4(y / float<radiance>(1.0));\n}\n")
  _write(generic_chain ${n} "${body}")
endfunction()

function(operator_chain n)
  set(body "out vec4 fragColor;\nvoid main() {\n    float<length> x = float<length>(1.0);\n    float<length> y = x\n")
  foreach(i RANGE 1 ${n})
    string(APPEND body "        * x / x\n")
  endforeach()
  string(APPEND body "        ;\n    fragColor = vec4(y / x);\n}\n")
  _write(operator_chain ${n} "${body}")
endfunction()

function(swizzle_chain n)
  string(REPEAT "        .xyzw\n" ${n} swizzles)
  _write(swizzle_chain ${n} "out vec4 fragColor;\nvoid main() {\n    vec4 v = vec4(1.0);\n    fragColor = v\n${swizzles}        ;\n}\n")
endfunction()

function(nested_parens n)
  string(REPEAT "(" ${n} open)
  string(REPEAT ")" ${n} close)
  _write(nested_parens ${n} "out vec4 fragColor;\nvoid main() {\n    float<length> x = float<length>(1.0);\n    float<length> y =\n${open}\nx\n${close};\n    fragColor = vec4(y / x);\n}\n")
endfunction()

file(MAKE_DIRECTORY ${OUT_DIR})
foreach(size IN LISTS SIZES)
  string(REPLACE "=" ";" parts "${size}")
  list(GET parts 0 kind)
  list(GET parts 1 n)
  cmake_language(CALL ${kind} ${n})
endforeach()
