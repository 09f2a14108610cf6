# Runs doxygen on doc/Doxyfile with the output directory moved to OUT_DIR, and fails if doxygen
# prints any warning. Called by the doc_doxygen test: cmake -DDOXYGEN=... -DSOURCE_DIR=... -DOUT_DIR=... -P this file
file(READ "${SOURCE_DIR}/doc/Doxyfile" config)
file(MAKE_DIRECTORY "${OUT_DIR}")
file(WRITE "${OUT_DIR}/Doxyfile" "${config}\nOUTPUT_DIRECTORY = ${OUT_DIR}\n")
execute_process(COMMAND "${DOXYGEN}" "${OUT_DIR}/Doxyfile"
                WORKING_DIRECTORY "${SOURCE_DIR}"
                RESULT_VARIABLE result
                OUTPUT_QUIET
                ERROR_VARIABLE warnings)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "doxygen failed (exit code ${result}):\n${warnings}")
endif()
string(STRIP "${warnings}" warnings)
if(NOT warnings STREQUAL "")
  message(FATAL_ERROR "doxygen warnings:\n${warnings}")
endif()
message(STATUS "documentation built in ${OUT_DIR}/html without warnings")
