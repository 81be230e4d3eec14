# Sets ARGINE_PLOT_PYTHON to a Python 3 interpreter that can import matplotlib (Debian's
# python3-matplotlib lives in /usr/bin/python3, which a pyenv or venv python3 on the PATH may
# shadow), or leaves it empty. Included by the verification case folders.
if(NOT DEFINED ARGINE_PLOT_PYTHON)
  find_package(Python3 COMPONENTS Interpreter QUIET)
  set(_candidates /usr/bin/python3)
  if(Python3_Interpreter_FOUND)
    list(APPEND _candidates "${Python3_EXECUTABLE}")
  endif()
  set(_found "")
  foreach(_python IN LISTS _candidates)
    if(NOT _found AND EXISTS "${_python}")
      execute_process(COMMAND "${_python}" -c "import matplotlib"
                      RESULT_VARIABLE _result OUTPUT_QUIET ERROR_QUIET)
      if(_result EQUAL 0)
        set(_found "${_python}")
      endif()
    endif()
  endforeach()
  if(NOT _found)
    message(STATUS "verification plots: no python3 with matplotlib, plot tests skipped")
  endif()
  set(ARGINE_PLOT_PYTHON "${_found}" CACHE INTERNAL "python3 with matplotlib for the plots")
endif()
