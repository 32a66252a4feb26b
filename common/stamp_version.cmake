# Writes version.cc with the current git commit; rewrites it only when the
# text changes so an unchanged tree does not relink everything.
execute_process(COMMAND git describe --always --dirty --abbrev=12
                WORKING_DIRECTORY ${SRC_DIR} OUTPUT_VARIABLE COOLGAS_GIT
                OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT COOLGAS_GIT)
  set(COOLGAS_GIT "no-git")
endif()
configure_file(${IN_FILE} ${OUT_FILE}.tmp @ONLY)
file(COPY_FILE ${OUT_FILE}.tmp ${OUT_FILE} ONLY_IF_DIFFERENT)
