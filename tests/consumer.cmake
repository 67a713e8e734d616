# libraytrace as its users see it (tests/consumer/): install this build into
# a fresh prefix under the build tree, then build and run a small program
# against it with find_package(raytrace) and with the plain pkg-config
# line; embed the source tree in a parent project with add_subdirectory and
# with FetchContent; build it shared, install it into a prefix and run its
# programs from there; and keep README.md's example identical to
# tests/consumer/example.c, which is compiled and run here.  Steps:
# tests/consumer/steps.cmake.  Labelled consumer: they build and link
# without the sanitizers, so .ci/sanitize and .ci/memcheck leave them out.
set(RT_CONSUMER_STEPS "${CMAKE_CURRENT_SOURCE_DIR}/consumer/steps.cmake")
set(RT_CONSUMER_ARGS
  "-DSOURCE_DIR=${PROJECT_SOURCE_DIR}"
  "-DBINARY_DIR=${PROJECT_BINARY_DIR}"
  "-DLIBDIR=${CMAKE_INSTALL_LIBDIR}"
  "-DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/consumer"
  "-DCONFIG=$<CONFIG>"
  "-DGENERATOR=${CMAKE_GENERATOR}"
  "-DC_COMPILER=${CMAKE_C_COMPILER}"
  "-DPKG_CONFIG=${PKG_CONFIG_EXECUTABLE}"
  "-DNM=${CMAKE_NM}")

function(raytrace_add_consumer_test name step)
  add_test(NAME ${name} COMMAND "${CMAKE_COMMAND}" ${RT_CONSUMER_ARGS}
           -DSTEP=${step} -P "${RT_CONSUMER_STEPS}")
  set_tests_properties(${name} PROPERTIES LABELS consumer ${ARGN})
endfunction()

raytrace_add_consumer_test(install_puts_the_package_in_a_prefix install
  FIXTURES_SETUP raytrace_installed)
raytrace_add_consumer_test(find_package_consumer_builds_against_the_install
  build FIXTURES_REQUIRED raytrace_installed FIXTURES_SETUP consumer_built)
raytrace_add_consumer_test(find_package_consumer_renders run
  FIXTURES_REQUIRED consumer_built)
raytrace_add_consumer_test(readme_example_renders_one_facet_scene example
  FIXTURES_REQUIRED consumer_built)
raytrace_add_consumer_test(readme_example_is_tests_consumer_example_c readme)
if(PKG_CONFIG_EXECUTABLE)
  raytrace_add_consumer_test(pkg_config_plain_line_builds_and_renders
    pkg-config FIXTURES_REQUIRED raytrace_installed)
endif()

# A parent project with its own test_parse and no build type.
raytrace_add_consumer_test(add_subdirectory_parent_gets_only_the_libraries
  subdirectory)
raytrace_add_consumer_test(fetchcontent_parent_gets_only_the_libraries
  fetchcontent)

# A shared build in a prefix of its own.
raytrace_add_consumer_test(shared_build_installs_into_a_prefix shared-install
  FIXTURES_SETUP raytrace_shared_installed)
raytrace_add_consumer_test(shared_build_programs_run_from_a_moved_prefix
  shared-run FIXTURES_REQUIRED raytrace_shared_installed)
raytrace_add_consumer_test(shared_library_exports_only_the_rt_api
  shared-symbols FIXTURES_REQUIRED raytrace_shared_installed
  SKIP_REGULAR_EXPRESSION "CONSUMER-SKIP: ")
if(PKG_CONFIG_EXECUTABLE)
  raytrace_add_consumer_test(shared_build_pkg_config_plain_line_links
    shared-pkg-config FIXTURES_REQUIRED raytrace_shared_installed)
endif()
