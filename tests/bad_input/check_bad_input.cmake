## Runs the application on one invalid parameter file and checks that it fails cleanly: it
## ends by itself (a hung rank is a failure), with a non-zero exit code and the expected
## message. The expected message comes from -DEXPECT or else from the file's first line;
## -DLAUNCHER (a list, e.g. mpiexec;-np;2) runs it on several ranks; without -DPRM the
## program runs without arguments.
if(DEFINED EXPECT)
  set(_expected "${EXPECT}")
else()
  file(STRINGS ${PRM} _first_line LIMIT_COUNT 1)
  string(REGEX REPLACE "^# expect: *" "" _expected "${_first_line}")
  if("${_expected}" STREQUAL "${_first_line}")
    message(FATAL_ERROR "${PRM}: the first line must read '# expect: <regex>'.")
  endif()
endif()
execute_process(COMMAND ${LAUNCHER} ${APP} ${PRM}
  RESULT_VARIABLE _result OUTPUT_VARIABLE _out ERROR_VARIABLE _err TIMEOUT 120)
set(_all "${_out}${_err}")
if(NOT "${_result}" MATCHES "^[0-9]+$")
  message(FATAL_ERROR "The run did not end by itself (${_result}). Output:\n${_all}")
endif()
if("${_result}" STREQUAL "0")
  message(FATAL_ERROR "Exit code 0 for an invalid input. Output:\n${_all}")
endif()
if(NOT "${_all}" MATCHES "${_expected}")
  message(FATAL_ERROR "Exit code ${_result}, but the message does not match '${_expected}':\n${_all}")
endif()
if("${_all}" MATCHES "Segmentation|Aborting!|signal")
  message(FATAL_ERROR "The application crashed instead of reporting the error:\n${_all}")
endif()
message(STATUS "Rejected as expected (exit code ${_result}):\n${_all}")
