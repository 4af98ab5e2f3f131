# A generated page must equal what its generator writes today, so a reader never
# sees a message the compiler no longer prints.
#   cmake -DGENERATOR=<script> -DDOC=<committed page> -DOUT=<scratch file> [-DCXX=<compiler>]
#         -P check_generated_doc.cmake
# The compiler's version line is compared loosely: a Debian point release of
# g++ that prints the same messages does not make the page stale.
if(CXX)
  set(ENV{CXX} ${CXX})
endif()
execute_process(COMMAND bash ${GENERATOR} ${OUT} RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${GENERATOR} failed (${status}):\n${output}")
endif()
file(READ ${DOC} committed)
file(READ ${OUT} regenerated)
foreach(text IN ITEMS committed regenerated)
  string(REGEX REPLACE "What `[^`]*` prints" "What `<compiler>` prints" ${text} "${${text}}")
endforeach()
if(NOT committed STREQUAL regenerated)
  execute_process(COMMAND diff -u ${DOC} ${OUT} OUTPUT_VARIABLE difference)
  message(FATAL_ERROR "${DOC} is stale; regenerate it with ${GENERATOR}\n${difference}")
endif()
