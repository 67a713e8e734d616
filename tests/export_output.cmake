# Where rt-export's image goes: standard output, standard input, formats,
# PNG, FIFOs, early refusals, signals (tests/test_export_output.c).
find_package(Threads REQUIRED)
# (RT_EXPORT_PATH and RT_CONVERT_PATH come from raytrace_add_suite.)
raytrace_add_suite(test_export_output LIBS Threads::Threads)
if(RAYTRACE_HAVE_PNG)
  target_link_libraries(raytrace_test_export_output PRIVATE PNG::PNG)
  target_compile_definitions(raytrace_test_export_output PRIVATE
    RT_TEST_HAVE_PNG=1)
else()
  target_compile_definitions(raytrace_test_export_output PRIVATE
    RT_TEST_HAVE_PNG=0)
endif()
set_tests_properties(test_export_output PROPERTIES TIMEOUT 600)
