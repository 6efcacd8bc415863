# Which Python interpreter the module lpvid._lpvid is built for. An extension
# only loads into the interpreter (version and ABI) it was built against, so
# the choice is explicit, not "the first python3 on PATH" (which may be a
# pyenv shim or a virtual environment without numpy):
#   1. -DPython3_EXECUTABLE=<path>, when given (pip's build passes its own
#      interpreter, sys.executable);
#   2. else the system's /usr/bin/python3 when it exists (Debian's, with
#      python3-numpy and python3-dev);
#   3. else FindPython3's own search.
# Configure prints the choice and its reason.
if(DEFINED Python3_EXECUTABLE)
  set(LPVID_PYTHON_INTERPRETER_REASON "given by -DPython3_EXECUTABLE")
elseif(EXISTS /usr/bin/python3)
  # a plain variable, not cached: a later -DPython3_EXECUTABLE still wins
  set(Python3_EXECUTABLE /usr/bin/python3)
  set(LPVID_PYTHON_INTERPRETER_REASON "the system's interpreter (no -DPython3_EXECUTABLE given)")
else()
  set(LPVID_PYTHON_INTERPRETER_REASON "FindPython3's search (no -DPython3_EXECUTABLE, no /usr/bin/python3)")
endif()

function(lpvid_report_python_interpreter)
  if(Python3_Interpreter_FOUND)
    message(STATUS "Python module built for ${Python3_EXECUTABLE} (Python ${Python3_VERSION}): "
                   "${LPVID_PYTHON_INTERPRETER_REASON}")
  else()
    message(STATUS "No Python 3 interpreter found (${LPVID_PYTHON_INTERPRETER_REASON})")
  endif()
endfunction()
