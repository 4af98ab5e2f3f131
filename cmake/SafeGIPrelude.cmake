# The shader prelude, safegi/prelude.sgl, made from the vocabulary (typed/include/safegi/typed/
# vocabulary.def): the one list of dimensions and units that C++, shaders and scene files take.
# Adding a unit touches vocabulary.def alone; the build writes the prelude again.
#
#   safegi_generate_prelude(<vocabulary.def> <prelude.sgl>)
#
# runs when CMake configures, and again whenever vocabulary.def or this file changes (they are
# configure dependencies), so compiler/ can embed the text and lsp/ and the tests name the file.
# The file is written only when its text changes. Also a script:
#
#   cmake -DVOCABULARY=<vocabulary.def> -DPRELUDE=<prelude.sgl> -P cmake/SafeGIPrelude.cmake
#
# What goes in the prelude, line by line of vocabulary.def:
#   VOCABULARY_BASE(name)                     dimension name;
#   VOCABULARY_RATIO_BASE(name)               dimension name : ratio;
#   VOCABULARY_DIMENSION(name, L.., "f")      dimension name = f;
#   VOCABULARY_SYNONYM(name, of)              dimension name = <of's formula>;
#   VOCABULARY_UNIT(name, "sym", dim, scale)  unit name : dim = scale;   (scale as written)
#   VOCABULARY_UNIT_ALIAS(alias, of)          unit alias : <of's dimension> = of;
#   VOCABULARY_CXX_UNIT(...)                  nothing (a unit of C++ alone)
#   /// text                                  // text   (a comment shaders read too)
#   an empty line                             an empty line (between groups; never first or last)
# A `//` comment and the preprocessor lines are C++'s alone. Any other line that starts with
# VOCABULARY_ is an error, so an entry the generator cannot read is never dropped.

# The header names vocabulary.def, the file to edit. Its text is part of every symbol table's
# source_hash of a shader that includes the prelude (the hash covers the included text), so a
# change here changes every table: keep it as it is unless the tables are regenerated too.
set(_SAFEGI_PRELUDE_HEADER
"// The SafeGI prelude, for shaders: typed/include/safegi/typed/vocabulary.def's names in its
// order (typechecker/src/prelude_test.cpp). `#include <safegi/prelude.sgl>`; see
// docs/language.md. Only annotation declarations: the whole file erases to nothing.
")

# The prelude's text for the vocabulary file `def`, in `out_var`.
function(safegi_prelude_text def out_var)
  file(READ "${def}" _text)
  # One list element per line: semicolons and brackets would split or join CMake list elements.
  string(REPLACE ";" "@SEMICOLON@" _text "${_text}")
  string(REPLACE "[" "@LBRACKET@" _text "${_text}")
  string(REPLACE "]" "@RBRACKET@" _text "${_text}")
  string(REPLACE "\n" ";" _lines "${_text}")
  set(_name "[a-z_][a-z0-9_]*")
  set(_int " *(-?[0-9]+) *")
  set(_out "${_SAFEGI_PRELUDE_HEADER}")
  set(_blank TRUE)  # the header is followed by an empty line
  set(_number 0)
  foreach(_line IN LISTS _lines)
    math(EXPR _number "${_number} + 1")
    string(REPLACE "@SEMICOLON@" ";" _line "${_line}")
    string(REPLACE "@LBRACKET@" "[" _line "${_line}")
    string(REPLACE "@RBRACKET@" "]" _line "${_line}")
    string(STRIP "${_line}" _stripped)
    set(_emit "")
    if(_stripped STREQUAL "")
      set(_blank TRUE)
      continue()
    elseif(_line MATCHES "^///( .*)?$")
      set(_emit "//${CMAKE_MATCH_1}")
    elseif(_line MATCHES "^VOCABULARY_BASE\\((${_name})\\)")
      set(_emit "dimension ${CMAKE_MATCH_1};")
    elseif(_line MATCHES "^VOCABULARY_RATIO_BASE\\((${_name})\\)")
      set(_emit "dimension ${CMAKE_MATCH_1} : ratio;")
    elseif(_line MATCHES "^VOCABULARY_DIMENSION\\((${_name}),${_int},${_int},${_int},${_int},${_int},${_int}, *\"([^\"]+)\"\\)")
      set(_formula_${CMAKE_MATCH_1} "${CMAKE_MATCH_8}")
      set(_emit "dimension ${CMAKE_MATCH_1} = ${CMAKE_MATCH_8};")
    elseif(_line MATCHES "^VOCABULARY_SYNONYM\\((${_name}), *(${_name})\\)")
      if(NOT DEFINED _formula_${CMAKE_MATCH_2})
        message(FATAL_ERROR "${def}:${_number}: synonym of '${CMAKE_MATCH_2}', no earlier dimension")
      endif()
      set(_formula_${CMAKE_MATCH_1} "${_formula_${CMAKE_MATCH_2}}")
      set(_emit "dimension ${CMAKE_MATCH_1} = ${_formula_${CMAKE_MATCH_2}};")
    elseif(_line MATCHES "^VOCABULARY_UNIT\\((${_name}), *\"[^\"]*\", *(${_name}), *([^ )]+) *\\)")
      set(_unit_${CMAKE_MATCH_1} "${CMAKE_MATCH_2}")
      set(_emit "unit ${CMAKE_MATCH_1} : ${CMAKE_MATCH_2} = ${CMAKE_MATCH_3};")
    elseif(_line MATCHES "^VOCABULARY_UNIT_ALIAS\\((${_name}), *(${_name})\\)")
      if(NOT DEFINED _unit_${CMAKE_MATCH_2})
        message(FATAL_ERROR "${def}:${_number}: alias of '${CMAKE_MATCH_2}', no earlier unit")
      endif()
      set(_emit "unit ${CMAKE_MATCH_1} : ${_unit_${CMAKE_MATCH_2}} = ${CMAKE_MATCH_2};")
    elseif(_line MATCHES "^VOCABULARY_CXX_UNIT\\(")
      continue()  # C++'s alone
    elseif(_line MATCHES "^VOCABULARY_")
      message(FATAL_ERROR "${def}:${_number}: cannot read '${_line}' (cmake/SafeGIPrelude.cmake lists the forms)")
    else()
      continue()  # a C++ comment, a preprocessor line
    endif()
    if(_blank)
      string(APPEND _out "\n")
      set(_blank FALSE)
    endif()
    string(APPEND _out "${_emit}\n")
  endforeach()
  set(${out_var} "${_out}" PARENT_SCOPE)
endfunction()

function(safegi_generate_prelude def prelude)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${def}" "${CMAKE_CURRENT_FUNCTION_LIST_FILE}")
  safegi_prelude_text("${def}" _text)
  if(EXISTS "${prelude}")
    file(READ "${prelude}" _old)
    if(_old STREQUAL _text)
      return()
    endif()
  endif()
  file(WRITE "${prelude}" "${_text}")
endfunction()

if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
  if(NOT VOCABULARY OR NOT PRELUDE)
    message(FATAL_ERROR "usage: cmake -DVOCABULARY=<vocabulary.def> -DPRELUDE=<prelude.sgl> -P ${CMAKE_CURRENT_LIST_FILE}")
  endif()
  safegi_prelude_text("${VOCABULARY}" _text)
  file(WRITE "${PRELUDE}" "${_text}")
endif()
