# docs/lessons.md's "Claims per lesson" is what `forcelab-cli check
# --markdown` prints: run it and compare with the text between the markers.
#   cmake -DCLI=... -DDOCS=... -P check_docs_claims.cmake
execute_process(COMMAND "${CLI}" check --markdown OUTPUT_VARIABLE generated RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "forcelab-cli check --markdown failed (exit ${status}): a claim does not hold")
endif()
file(READ "${DOCS}" docs)
set(begin "<!-- claims: begin (forcelab-cli check --markdown) -->\n")
set(end "<!-- claims: end -->")
string(FIND "${docs}" "${begin}" from)
string(FIND "${docs}" "${end}" to)
if(from EQUAL -1 OR to EQUAL -1)
  message(FATAL_ERROR "${DOCS}: the claims markers are missing")
endif()
string(LENGTH "${begin}" skip)
math(EXPR from "${from} + ${skip}")
math(EXPR length "${to} - ${from}")
string(SUBSTRING "${docs}" ${from} ${length} written)
if(NOT written STREQUAL generated)
  message(FATAL_ERROR "${DOCS}: the claims list is out of date; rewrite it with: "
                      "build/app/forcelab-cli check --markdown (between the claims markers)")
endif()
