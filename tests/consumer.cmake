# The installed package, as its users see it (tests/consumer/): install this
# build into a fresh prefix under the build tree, then build and run a small
# program against it with find_package(raytrace) and with pkg-config; and
# keep README.md's example identical to tests/consumer/example.c, which is
# compiled and run here.  Steps: tests/consumer/steps.cmake.
set(RT_CONSUMER_STEPS "${CMAKE_CURRENT_SOURCE_DIR}/consumer/steps.cmake")
set(RT_CONSUMER_ARGS
  "-DSOURCE_DIR=${PROJECT_SOURCE_DIR}"
  "-DBINARY_DIR=${PROJECT_BINARY_DIR}"
  "-DLIBDIR=${CMAKE_INSTALL_LIBDIR}"
  "-DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/consumer"
  "-DCONFIG=$<CONFIG>"
  "-DGENERATOR=${CMAKE_GENERATOR}"
  "-DC_COMPILER=${CMAKE_C_COMPILER}"
  "-DPKG_CONFIG=${PKG_CONFIG_EXECUTABLE}")

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
  raytrace_add_consumer_test(pkg_config_consumer_builds_and_renders
    pkg-config FIXTURES_REQUIRED raytrace_installed)
endif()
