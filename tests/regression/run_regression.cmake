cmake_minimum_required(VERSION 3.13)
## Runs one regression case and compares its energy history with the stored one by numdiff.
## The case file <name>.prm names the shipped parameter file it shortens and the tolerances:
##   # regression: parameter_files/<file>.prm
##   # relative tolerance: <r> (why)
##   # absolute tolerance: <a> (why)
##   # ranks: 1 2                      (optional: also run as <name>.mpirun=2)
## then the entries that shorten it. The runner writes case.prm: 'include' of the shipped file,
## the test's entries (@SOURCE_DIR@ replaced by the source tree) and the output entries below;
## runs the application (-DLAUNCHER for several ranks); and compares regression_energy.csv
## with <name>.csv: every number within the relative or the absolute tolerance (numdiff).
## PERIARLEQUIN_UPDATE_REGRESSION=1 in the environment writes the reference instead (-DRANKS
## names the rank count, for a reference of its own).
file(READ ${PRM} _text)
string(REGEX MATCH "# regression: ([^\n]*)" _ ${_text})
set(_shipped "${CMAKE_MATCH_1}")
string(REGEX MATCH "# relative tolerance: ([0-9.eE+-]+)" _ ${_text})
set(_relative "${CMAKE_MATCH_1}")
string(REGEX MATCH "# absolute tolerance: ([0-9.eE+-]+)" _ ${_text})
set(_absolute "${CMAKE_MATCH_1}")
if(NOT _shipped OR NOT _relative OR NOT _absolute)
  message(FATAL_ERROR "${PRM}: the header must name the shipped file and both tolerances.")
endif()
string(REPLACE "@SOURCE_DIR@" "${SOURCE_DIR}" _entries "${_text}")
file(WRITE case.prm "include ${SOURCE_DIR}/${_shipped}\n${_entries}
subsection Output
  set Directory = .
  set Base name = regression
  set Output interval = 0
  set Energy interval = 1
  set Progress interval = 0
  set Print timing summary = false
end
")
file(REMOVE regression_energy.csv)
execute_process(COMMAND ${LAUNCHER} ${APP} case.prm
  RESULT_VARIABLE _result OUTPUT_VARIABLE _out ERROR_VARIABLE _err TIMEOUT 600)
if(NOT "${_result}" STREQUAL "0")
  message(FATAL_ERROR "The case failed (${_result}):\n${_out}${_err}")
endif()
get_filename_component(_name ${PRM} NAME_WE)
get_filename_component(_dir ${PRM} DIRECTORY)
# Columns that depend on the rank count (load imbalance, repartitions) need a reference of
# their own: <name>.mpirun=N.csv where it exists.
set(_reference ${_dir}/${_name}.csv)
if(RANKS AND EXISTS ${_dir}/${_name}.mpirun=${RANKS}.csv)
  set(_reference ${_dir}/${_name}.mpirun=${RANKS}.csv)
endif()
# Updating: the 1-rank run writes <name>.csv; a run on N ranks writes only a reference of its
# own (<name>.mpirun=N.csv, where one exists) and is compared with <name>.csv otherwise.
if("$ENV{PERIARLEQUIN_UPDATE_REGRESSION}" STREQUAL "1" AND
   (NOT RANKS OR RANKS EQUAL 1 OR _reference MATCHES "mpirun="))
  file(COPY_FILE regression_energy.csv ${_reference})
  message(STATUS "Wrote ${_reference}")
  return()
endif()
execute_process(COMMAND ${NUMDIFF} -a ${_absolute} -r ${_relative} -s " \t\n,"
  ${_reference} regression_energy.csv
  RESULT_VARIABLE _differ OUTPUT_VARIABLE _diff)
if(NOT "${_differ}" STREQUAL "0")
  string(SUBSTRING "${_diff}" 0 3000 _diff)
  message(FATAL_ERROR "The energy history differs from ${_reference} by more than "
    "relative ${_relative} / absolute ${_absolute}:\n${_diff}")
endif()
message(STATUS "Energy history within relative ${_relative} / absolute ${_absolute} of "
  "${_reference}")
