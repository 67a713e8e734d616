# Where rt-export's image goes: standard output, standard input, formats,
# PNG, FIFOs, early refusals, signals (tests/test_export_output.c).
find_package(Threads REQUIRED)
raytrace_add_suite(test_export_output LIBS Threads::Threads)
target_compile_definitions(test_export_output PRIVATE
  RT_EXPORT_PATH="$<TARGET_FILE:rt-export>"
  RT_CONVERT_PATH="$<TARGET_FILE:rt-convert>")
add_dependencies(test_export_output rt-export rt-convert)
if(RAYTRACE_HAVE_PNG)
  target_link_libraries(test_export_output PRIVATE PNG::PNG)
  target_compile_definitions(test_export_output PRIVATE RT_TEST_HAVE_PNG=1)
else()
  target_compile_definitions(test_export_output PRIVATE RT_TEST_HAVE_PNG=0)
endif()
set_tests_properties(test_export_output PROPERTIES TIMEOUT 600)
