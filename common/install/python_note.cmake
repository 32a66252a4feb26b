# Run by `cmake --install` last (install.cmake): says where the Python
# package went, and whether the interpreter it was built for finds it there
# or needs PYTHONPATH. Set before it: COOLGAS_PYTHON (the interpreter) and
# COOLGAS_PYTHON_DIR (the package's folder, relative to the prefix).
set(dir "${CMAKE_INSTALL_PREFIX}/${COOLGAS_PYTHON_DIR}")
get_filename_component(parent "${dir}" DIRECTORY)
execute_process(COMMAND "${COOLGAS_PYTHON}" -c "import sys; sys.exit(0 if sys.argv[1] in sys.path else 1)" "${parent}"
                RESULT_VARIABLE found OUTPUT_QUIET ERROR_QUIET)
if(found EQUAL 0)
  message(STATUS "coolgas: the Python package is in ${dir}; ${COOLGAS_PYTHON} finds it there (import coolgas)")
else()
  message(STATUS "coolgas: the Python package is in ${dir}; ${COOLGAS_PYTHON} finds it with PYTHONPATH=${parent}")
endif()
