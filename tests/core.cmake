# The core library's Check suites, one per module (STYLE.md point 10).
# Included from tests/CMakeLists.txt, which defines raytrace_add_suite().
foreach(suite
    test_vec
    test_parse
    test_parse_accepts
    test_camera
    test_intersect
    test_shade
    test_reflect
    test_ppm
    test_render
    test_render_size
    test_extension
    test_readers
    test_api
    test_api_edges
    test_api_accessors
    test_shading
    test_smooth
    test_look)
  raytrace_add_suite(${suite})
endforeach()
# The accessors' bad calls, tests/test_api_accessors.c: in a debug build
# each must abort naming its function (test_api_accessors); where NDEBUG
# compiles asserts out (Release) each returns its zero value
# (test_api_accessors_fallbacks).  The entry that does not apply to the
# build exits 77, a visible skip.
add_test(NAME test_api_accessors_fallbacks
         COMMAND raytrace_test_api_accessors fallbacks
         WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
set_tests_properties(test_api_accessors test_api_accessors_fallbacks
  PROPERTIES SKIP_RETURN_CODE 77)
# The handout's seed scenes, skipped when ../shared is absent.
raytrace_add_shared_test(test_render)

# The parser must read numbers in the C locale whatever the process's locale.
# Most build machines have no French locale installed; when localedef can make
# one into the build tree, test_parse_accepts (whose locale test it is) gets
# it through LOCPATH.  Without it the test falls back to another locale and
# says so in its output.
find_program(RAYTRACE_LOCALEDEF localedef)
if(RAYTRACE_LOCALEDEF)
  set(rt_locale_dir "${CMAKE_CURRENT_BINARY_DIR}/locale")
  if(NOT EXISTS "${rt_locale_dir}/fr_FR.UTF-8/LC_NUMERIC")
    file(MAKE_DIRECTORY "${rt_locale_dir}")
    execute_process(
      COMMAND "${RAYTRACE_LOCALEDEF}" -i fr_FR -f UTF-8
              "${rt_locale_dir}/fr_FR.UTF-8"
      RESULT_VARIABLE rt_localedef_result
      OUTPUT_QUIET ERROR_QUIET)
  endif()
  if(EXISTS "${rt_locale_dir}/fr_FR.UTF-8/LC_NUMERIC")
    set_tests_properties(test_parse_accepts PROPERTIES
      ENVIRONMENT "LOCPATH=${rt_locale_dir}")
  else()
    message(STATUS "test_parse_accepts: could not build fr_FR.UTF-8 with "
                   "localedef; "
                   "the locale test uses whatever locale is installed")
  endif()
endif()

# The layering of docs/architecture.md on the source tree as it is: no
# include up a layer or across, no file of src/ or apps/ over 700 lines
# (tests/test_layers.c); no include circle (tests/test_layers_circles.c).
# tests/layers.allow lists the violations known while they are being
# removed, and only shrinks.
raytrace_add_suite(test_layers)
raytrace_add_suite(test_layers_circles)
