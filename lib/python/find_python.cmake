# find_python.cmake: decides SHADETOOL_PYTHON and finds the interpreter the module is built for.
#
# The interpreter: Python3_EXECUTABLE if given, else PYTHON_EXECUTABLE if given, else Debian's
# /usr/bin/python3 when it exists (a python3 first on PATH, e.g. pyenv's, may lack NumPy or the
# development files), else whatever FindPython finds. The tests (tests/CMakeLists.txt) run the same
# interpreter, Python3_EXECUTABLE.
# SHADETOOL_PYTHON: ON by default when the interpreter, its development files (python3-dev), NumPy
# (python3-numpy) and pybind11 (pybind11-dev) are all found, OFF otherwise with a message saying
# what is missing. -DSHADETOOL_PYTHON=OFF skips the search; ON makes a missing piece an error.
if(DEFINED SHADETOOL_PYTHON AND NOT SHADETOOL_PYTHON)
  return()
endif()
if(NOT DEFINED Python3_EXECUTABLE)
  if(DEFINED PYTHON_EXECUTABLE)
    set(Python3_EXECUTABLE "${PYTHON_EXECUTABLE}" CACHE FILEPATH "Python interpreter the module is built for")
  elseif(EXISTS /usr/bin/python3)
    set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter the module is built for")
  endif()
endif()
if(DEFINED SHADETOOL_PYTHON)  # asked for explicitly: anything missing is an error
  find_package(Python3 REQUIRED COMPONENTS Interpreter Development.Module NumPy)
  find_package(pybind11 CONFIG REQUIRED)
  return()
endif()
find_package(Python3 QUIET COMPONENTS Interpreter Development.Module NumPy)
find_package(pybind11 CONFIG QUIET)
set(missing "")
if(NOT Python3_Interpreter_FOUND)
  list(APPEND missing "a Python 3 interpreter (python3)")
endif()
if(NOT Python3_Development.Module_FOUND)
  list(APPEND missing "Python 3 development files (python3-dev)")
endif()
if(NOT Python3_NumPy_FOUND)
  list(APPEND missing "NumPy (python3-numpy)")
endif()
if(NOT pybind11_FOUND)
  list(APPEND missing "pybind11 (pybind11-dev)")
endif()
if(missing)
  list(JOIN missing ", " missing_text)
  message(STATUS "Python module: OFF (not found: ${missing_text})")
  option(SHADETOOL_PYTHON "Build the Python module shadetool (lib/python)" OFF)
else()
  message(STATUS "Python module: ON (${Python3_EXECUTABLE}, Python ${Python3_VERSION}, NumPy ${Python3_NumPy_VERSION}, pybind11 ${pybind11_VERSION})")
  option(SHADETOOL_PYTHON "Build the Python module shadetool (lib/python)" ON)
endif()
