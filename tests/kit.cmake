# The course's whole kit: a student project written in the
# course's layout (tests/student/: its own src/, include/, tests/ and a
# course-style Makefile) is built with make against the libraries
# installed in a fresh prefix, as a student would: `make all`, `make
# tests` (the graded test's score), `make run` (its image against
# rt-export's), `make tests_sdl` and `make run_sdl` (libimgsdl on SDL's
# dummy driver, IMGSDL_OUTPUT).  Steps: tests/kit_steps.cmake.  Labelled
# consumer: the student's make builds without the sanitizers, so the
# sanitizer and valgrind passes leave these out, as the other consumer
# tests.  A step that cannot run (no make, no SDL2) is a skipped test.
set(RT_KIT_DIR "${CMAKE_CURRENT_BINARY_DIR}/kit")

# The prefix: tests/consumer/steps.cmake's install step, into RT_KIT_DIR.
add_test(NAME kit_install_puts_the_course_kit_in_a_prefix
  COMMAND "${CMAKE_COMMAND}" ${RT_CONSUMER_ARGS} "-DWORK_DIR=${RT_KIT_DIR}"
          -DSTEP=install -P "${RT_CONSUMER_STEPS}")
set_tests_properties(kit_install_puts_the_course_kit_in_a_prefix PROPERTIES
  LABELS consumer FIXTURES_SETUP kit_installed)

function(raytrace_add_kit_test name step)
  add_test(NAME ${name} COMMAND "${CMAKE_COMMAND}"
    "-DSOURCE_DIR=${PROJECT_SOURCE_DIR}"
    "-DPREFIX=${RT_KIT_DIR}/prefix"
    "-DLIBDIR=${CMAKE_INSTALL_LIBDIR}"
    "-DWORK_DIR=${RT_KIT_DIR}"
    "-DC_COMPILER=${CMAKE_C_COMPILER}"
    "-DKIT_PPM=$<TARGET_FILE:raytrace_kit_ppm>"
    "-DPKG_CONFIG=${PKG_CONFIG_EXECUTABLE}"
    "-DGENERATOR=${CMAKE_GENERATOR}"
    -DSTEP=${step} -P "${CMAKE_CURRENT_SOURCE_DIR}/kit_steps.cmake")
  # One make at a time in the student's folder.
  set_tests_properties(${name} PROPERTIES LABELS consumer
    RESOURCE_LOCK kit_student SKIP_REGULAR_EXPRESSION "KIT-SKIP: " ${ARGN})
endfunction()

raytrace_add_kit_test(kit_student_project_make_all all
  FIXTURES_REQUIRED kit_installed FIXTURES_SETUP kit_built)
raytrace_add_kit_test(kit_student_project_make_tests_prints_full_score tests
  FIXTURES_REQUIRED kit_built)
raytrace_add_kit_test(kit_student_project_make_run_renders_as_rt_export run
  FIXTURES_REQUIRED kit_built FIXTURES_SETUP kit_ran)
raytrace_add_kit_test(kit_student_project_make_tests_sdl_draws_headless
  tests_sdl FIXTURES_REQUIRED kit_built)
raytrace_add_kit_test(kit_student_project_make_run_sdl_shows_make_runs_image
  run_sdl)
set_tests_properties(kit_student_project_make_run_sdl_shows_make_runs_image
  PROPERTIES FIXTURES_REQUIRED "kit_built;kit_ran")
raytrace_add_kit_test(kit_libraries_are_found_by_pkg_config_and_find_package
  packages FIXTURES_REQUIRED kit_installed)
# The -lm case: student code calling sqrt, with docs/in104.md's Makefile
# lines (kit_steps.cmake, STEP lm); its own copy of the project.
raytrace_add_kit_test(kit_student_sqrt_links_with_the_documented_makefile_lines
  lm FIXTURES_REQUIRED kit_installed)
