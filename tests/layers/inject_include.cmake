# Proof that an include check fails where it must (tests/layers/CMakeLists.txt):
#   cmake -DROOT=<repository> -DWORK=<scratch dir> -DFILE=<path under src/pathspace/> -DLINE=<n>
#         -DHEADER=<included path> -DEXPECT=<message> [-DCHECK=<script under cmake/>] -P inject_include.cmake
# copies ROOT/src/pathspace/ (and bench/cuda/) to WORK, inserts `#include "HEADER"` into FILE so that
# it becomes line LINE (FILE is created when it does not exist), runs the check (default
# PathspaceLayerCheck.cmake) on the copy and succeeds only if that check fails with the line
#   WORK/src/pathspace/FILE:LINE: EXPECT
cmake_minimum_required(VERSION 3.25)
foreach(var ROOT WORK FILE LINE HEADER EXPECT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "inject_include.cmake: -D${var}=... missing")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/src")
file(COPY "${ROOT}/src/pathspace" DESTINATION "${WORK}/src")
file(MAKE_DIRECTORY "${WORK}/bench")
file(COPY "${ROOT}/bench/cuda" DESTINATION "${WORK}/bench")
if(NOT DEFINED CHECK)
  set(CHECK PathspaceLayerCheck.cmake)
endif()
set(target "${WORK}/src/pathspace/${FILE}")
set(content "")
if(EXISTS "${target}")
  file(READ "${target}" content)
endif()
# Insert before the LINE-th line (a shorter file is padded with empty lines).
set(head "")
set(rest "${content}")
set(n 1)
while(n LESS LINE)
  string(FIND "${rest}" "\n" nl)
  if(nl EQUAL -1)
    string(APPEND head "${rest}\n")
    set(rest "")
  else()
    math(EXPR len "${nl} + 1")
    string(SUBSTRING "${rest}" 0 ${len} line)
    string(APPEND head "${line}")
    string(SUBSTRING "${rest}" ${len} -1 rest)
  endif()
  math(EXPR n "${n} + 1")
endwhile()
file(WRITE "${target}" "${head}#include \"${HEADER}\"\n${rest}")

execute_process(COMMAND "${CMAKE_COMMAND}" "-DROOT=${WORK}" -P "${ROOT}/cmake/${CHECK}"
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
set(expected "${target}:${LINE}: ${EXPECT}")
if(result EQUAL 0)
  message(FATAL_ERROR "${CHECK} passed, but ${FILE}:${LINE} includes ${HEADER}")
endif()
string(FIND "${out}" "${expected}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${CHECK} failed, but without the line\n  ${expected}")
endif()
file(REMOVE_RECURSE "${WORK}")
message(STATUS "${CHECK} rejects ${FILE}:${LINE} including ${HEADER}, as it must")
