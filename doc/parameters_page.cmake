## Writes the parameter reference page for Doxygen: the output of
## `periarlequin --print-parameters 2` and `3` (every entry, its default and documentation).
## Called by the doc target with -DAPP=<application> -DOUTPUT=<file>.
set(_page "/**\n@page parameters Parameter reference\n\nEvery entry of a parameter file, with its default and documentation, as\n`periarlequin --print-parameters <dimension>` prints it.\n")
foreach(_dim 2 3)
  execute_process(COMMAND ${APP} --print-parameters ${_dim}
    OUTPUT_VARIABLE _text RESULT_VARIABLE _result)
  if(NOT _result EQUAL 0)
    message(FATAL_ERROR "${APP} --print-parameters ${_dim} failed (${_result}).")
  endif()
  string(APPEND _page "\n@section parameters_${_dim}d Dimension = ${_dim}\n\n@verbatim\n${_text}@endverbatim\n")
endforeach()
string(APPEND _page "*/\n")
file(WRITE ${OUTPUT} "${_page}")
