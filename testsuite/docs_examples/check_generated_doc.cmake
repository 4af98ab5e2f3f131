# A generated page must equal what its generator writes today, so a reader never
# sees a message the compiler no longer prints.
#   cmake -DGENERATOR=<script> -DDOC=<committed page> -DOUT=<scratch file> [-DCXX=<compiler>]
#         [-DEXTRA_DOCS=<committed page>...] -P check_generated_doc.cmake
# EXTRA_DOCS are further pages the generator writes beside OUT under the same name.
# The compilers' version lines are compared loosely: a Debian point release of
# g++ or clang++ that prints the same messages does not make the page stale.
if(CXX)
  set(ENV{CXX} ${CXX})
endif()
execute_process(COMMAND bash ${GENERATOR} ${OUT} RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${GENERATOR} failed (${status}):\n${output}")
endif()

function(compare_generated committed_path regenerated_path)
  file(READ ${committed_path} committed)
  file(READ ${regenerated_path} regenerated)
  foreach(text IN ITEMS committed regenerated)
    string(REGEX REPLACE "What `[^`]*`( and `[^`]*`)? prints?" "What `<compilers>` print" ${text} "${${text}}")
  endforeach()
  if(NOT committed STREQUAL regenerated)
    execute_process(COMMAND diff -u ${committed_path} ${regenerated_path} OUTPUT_VARIABLE difference)
    message(SEND_ERROR "${committed_path} is stale; regenerate it with ${GENERATOR}\n${difference}")
  endif()
endfunction()

compare_generated(${DOC} ${OUT})
get_filename_component(out_dir ${OUT} DIRECTORY)
string(REPLACE "|" ";" extra_docs "${EXTRA_DOCS}")
foreach(extra IN LISTS extra_docs)
  get_filename_component(name ${extra} NAME)
  compare_generated(${extra} ${out_dir}/${name})
endforeach()
