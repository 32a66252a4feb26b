# What `cmake --install` puts beside the programs (bin/): a manual page for
# each (share/man/man1, made from its --help by help2man), bash completion,
# share/doc/coolgas/ with the documentation as it stands in the source tree
# (README, NEWS, LICENSE, docs/, data-schema/: the file formats --help
# names), and share/coolgas/ with the pipelines and their gnuplot scripts, so that
#   make -C PREFIX/share/coolgas/pipelines/demo
# runs the demo with the installed programs (pipelines/common.mk finds them).
get_property(COOLGAS_TOOLS GLOBAL PROPERTY COOLGAS_TOOLS)

# One line for each page's NAME section.
set(COOLGAS_MAN_NAME_coolgas-simulate "event-driven simulation of inelastic hard spheres and ballistic aggregation")
set(COOLGAS_MAN_NAME_coolgas-validate "check a trajectory against the coolgas H5MD profile")
set(COOLGAS_MAN_NAME_coolgas-energy "kinetic energy E(t) of runs and their ensemble mean")
set(COOLGAS_MAN_NAME_coolgas-fit "power-law, local-slope and Haff fits to E(t)")
set(COOLGAS_MAN_NAME_coolgas-collapse "finite-size scaling collapse of E(t) for several box sizes")
set(COOLGAS_MAN_NAME_coolgas-clusters "clusters by unit cells or by contact: N(m,t), largest and mean mass")
set(COOLGAS_MAN_NAME_coolgas-velocity "scaled velocity distribution, kurtosis and tail exponent")
set(COOLGAS_MAN_NAME_coolgas-snapshot "picture of a dump, particles coloured by cluster")
set(COOLGAS_MAN_NAME_coolgas-smoluchowski "mean-field cluster-size distribution from the Smoluchowski equation")
set(COOLGAS_MAN_NAME_coolgas-structure "structure factor S(k,t), the growing length L(t) and g(r)")
set(COOLGAS_MAN_NAME_coolgas-shape "cluster shapes: gyration tensors and fractal dimension")
set(COOLGAS_MAN_NAME_coolgas-displacement "mean-square displacement and velocity autocorrelation")
set(COOLGAS_MAN_NAME_coolgas-convert "dumps as extended XYZ or LAMMPS frames for other programs")
set(COOLGAS_MAN_NAME_coolgas-fields "density, flow and temperature fields; the flow's longitudinal and transverse energy")

# (COOLGAS_MAN: top CMakeLists.txt.)
if(COOLGAS_MAN AND NOT COOLGAS_SANITIZE)
  find_program(HELP2MAN help2man REQUIRED)
  set(man_dir ${CMAKE_BINARY_DIR}/man/man1)
  set(pages)
  foreach(tool IN LISTS COOLGAS_TOOLS)
    if(NOT DEFINED COOLGAS_MAN_NAME_${tool})
      message(FATAL_ERROR "${tool} has no manual page NAME line in common/install/install.cmake")
    endif()
    set(page ${man_dir}/${tool}.1)
    add_custom_command(OUTPUT ${page}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${man_dir}
      COMMAND ${HELP2MAN} --no-info --section=1 "--name=${COOLGAS_MAN_NAME_${tool}}" --output=${page}
              $<TARGET_FILE:${tool}>
      DEPENDS ${tool} VERBATIM)
    list(APPEND pages ${page})
  endforeach()
  add_custom_target(coolgas_man ALL DEPENDS ${pages})
  install(FILES ${pages} DESTINATION share/man/man1)
endif()

foreach(tool IN LISTS COOLGAS_TOOLS)
  install(FILES ${CMAKE_CURRENT_LIST_DIR}/coolgas.bash-completion
          DESTINATION share/bash-completion/completions RENAME ${tool})
endforeach()

# The documents keep their places relative to each other, so every link
# between them resolves in share/doc/coolgas as in the source tree
# (tests/cli/installed_tree.sh checks it).
set(COOLGAS_DOC_DIR share/doc/coolgas)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/NEWS.md ${PROJECT_SOURCE_DIR}/LICENSE
              ${PROJECT_SOURCE_DIR}/CITATION.cff ${PROJECT_SOURCE_DIR}/ARCHITECTURE.md
        DESTINATION ${COOLGAS_DOC_DIR})
foreach(dir docs data-schema tests/bench)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/ DESTINATION ${COOLGAS_DOC_DIR}/${dir} FILES_MATCHING PATTERN "*.md"
          PATTERN eta_scenes EXCLUDE)
endforeach()
install(FILES ${PROJECT_SOURCE_DIR}/pipelines/README.md DESTINATION ${COOLGAS_DOC_DIR}/pipelines)
install(FILES ${PROJECT_SOURCE_DIR}/tests/physics/README.md DESTINATION ${COOLGAS_DOC_DIR}/tests/physics)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/pipelines/ DESTINATION share/coolgas/pipelines USE_SOURCE_PERMISSIONS)

# Last: where the Python package went, and how its interpreter finds it.
get_property(python_dir GLOBAL PROPERTY COOLGAS_PYTHON_INSTALL_DIR)
if(python_dir)
  get_property(python GLOBAL PROPERTY COOLGAS_PYTHON_EXECUTABLE)
  install(CODE "set(COOLGAS_PYTHON \"${python}\")\nset(COOLGAS_PYTHON_DIR \"${python_dir}\")")
  install(SCRIPT ${CMAKE_CURRENT_LIST_DIR}/python_note.cmake)
endif()
