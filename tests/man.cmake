# The manual pages of man/: each renders without a warning from groff, and
# names every long option its program's --help lists, so that page and
# program cannot drift apart (tests/man_check.cmake).  Without groff
# (Debian: groff-base, which .ci/install-deps installs) the rendering check
# is a visible skip.
foreach(program rt-export rt-view rt-convert rt-export-mpi rt-bench
        in104-render)
  string(REPLACE "-" "_" target "raytrace_${program}")
  if(NOT TARGET ${target})
    continue()
  endif()
  string(REPLACE "-" "_" name "man_page_${program}")
  # rt-convert takes few: two of its own, two of the table, --help and
  # --version
  set(min_options 10)
  if(program STREQUAL "rt-convert")
    set(min_options 6)
  elseif(program STREQUAL "in104-render")
    set(min_options 2)          # --help and --version
  endif()
  add_test(NAME ${name}_names_every_option_of_its_help
    COMMAND "${CMAKE_COMMAND}" -DSTEP=options -DMIN_OPTIONS=${min_options}
            "-DPROGRAM=$<TARGET_FILE:${target}>"
            "-DPAGE=${PROJECT_SOURCE_DIR}/man/${program}.1"
            -P "${CMAKE_CURRENT_SOURCE_DIR}/man_check.cmake")
  add_test(NAME ${name}_renders_without_warnings
    COMMAND "${CMAKE_COMMAND}" -DSTEP=render
            "-DPAGE=${PROJECT_SOURCE_DIR}/man/${program}.1"
            -P "${CMAKE_CURRENT_SOURCE_DIR}/man_check.cmake")
  set_tests_properties(${name}_renders_without_warnings PROPERTIES
    SKIP_REGULAR_EXPRESSION "MAN-SKIP: ")
  if(program STREQUAL "rt-export-mpi")
    # Open MPI's own allocations, which LeakSanitizer cannot suppress by
    # name (tests/mpi.cmake): no leak check for this program's runs.
    set_tests_properties(${name}_names_every_option_of_its_help PROPERTIES
      ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0:abort_on_error=0")
  endif()
endforeach()

# Every installed program answers --help (usage on standard output) and
# --version ("PROG (libraytrace) <the project's version>"), both with exit
# status 0 (man_check.cmake, STEP=answers).
foreach(program rt-export rt-view rt-convert rt-export-mpi rt-bench
        in104-render)
  string(REPLACE "-" "_" target "raytrace_${program}")
  if(NOT TARGET ${target})
    continue()
  endif()
  string(REPLACE "-" "_" name "${program}")
  add_test(NAME program_${name}_answers_help_and_version
    COMMAND "${CMAKE_COMMAND}" -DSTEP=answers -DNAME=${program}
            "-DPROGRAM=$<TARGET_FILE:${target}>"
            "-DVERSION=${PROJECT_VERSION}"
            -P "${CMAKE_CURRENT_SOURCE_DIR}/man_check.cmake")
  if(program STREQUAL "rt-export-mpi")
    set_tests_properties(program_${name}_answers_help_and_version PROPERTIES
      ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0:abort_on_error=0")
  endif()
endforeach()
