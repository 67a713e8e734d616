# The one command-line module (issue 16): the parser in process, and
# rt-export, rt-bench and rt-view as a user runs them (tests/test_cli.c).
# `test_cli json` checks --stats=json with python3's json module and exits
# 77, a skip CTest shows, when python3 is absent.
raytrace_add_suite(test_cli LIBS raytrace_cli)
target_compile_definitions(test_cli PRIVATE
  RT_EXPORT_PATH="$<TARGET_FILE:rt-export>")
add_dependencies(test_cli rt-export)
foreach(program rt-bench rt-view)
  if(TARGET ${program})
    string(REPLACE "rt-" "RT_" macro "${program}")
    string(TOUPPER "${macro}_PATH" macro)
    target_compile_definitions(test_cli PRIVATE
      ${macro}="$<TARGET_FILE:${program}>")
    add_dependencies(test_cli ${program})
  endif()
endforeach()
set_tests_properties(test_cli PROPERTIES TIMEOUT 300)
add_test(NAME test_cli_json COMMAND test_cli json
         WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
set_tests_properties(test_cli_json PROPERTIES SKIP_RETURN_CODE 77
                     TIMEOUT 120)
