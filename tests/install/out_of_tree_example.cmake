## Install BUILD_DIR to WORK_DIR/prefix, build EXAMPLE_DIR against it, run its case.
function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE _result OUTPUT_VARIABLE _out
    ERROR_VARIABLE _err WORKING_DIRECTORY ${WORK_DIR})
  if(NOT "${_result}" STREQUAL "0")
    message(FATAL_ERROR "${what} failed (${_result}):\n${_out}${_err}")
  endif()
  set(_step_output "${_out}${_err}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
run_step("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix)
run_step("configuring the example" ${CMAKE_COMMAND} -S ${EXAMPLE_DIR} -B ${WORK_DIR}/build
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DDEAL_II_DIR=${DEAL_II_DIR})
run_step("building the example" ${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run_step("running the example" ${WORK_DIR}/build/user_plugins
  ${EXAMPLE_DIR}/user_plugins.prm --verify)
if(NOT "${_step_output}" MATCHES "verified")
  message(FATAL_ERROR "The example ran but was not verified:\n${_step_output}")
endif()
message(STATUS "${_step_output}")
