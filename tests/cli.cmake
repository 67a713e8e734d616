# The one command-line module: the parser in process, and
# rt-export, rt-bench and rt-view as a user runs them (tests/test_cli.c).
# `test_cli json` checks --stats=json with python3's json module and exits
# 77, a skip CTest shows, when python3 is absent.
# The programs' paths (RT_EXPORT_PATH, RT_BENCH_PATH, RT_VIEW_PATH) come
# from raytrace_add_suite.
raytrace_add_suite(test_cli LIBS raytrace_cli)
set_tests_properties(test_cli PROPERTIES TIMEOUT 300)
add_test(NAME test_cli_json COMMAND raytrace_test_cli json
         WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
set_tests_properties(test_cli_json PROPERTIES SKIP_RETURN_CODE 77
                     TIMEOUT 120)
# One grammar for a number, in a scene file and on the command line
# (tests/test_cli_numbers.c).
raytrace_add_suite(test_cli_numbers LIBS raytrace_cli)
set_tests_properties(test_cli_numbers PROPERTIES TIMEOUT 120)
# Every JSON output valid, whatever the names hold (tests/test_json_output.c):
# the string writer in process; `test_json_output_python` reads the
# programs' JSON with python3's json module, a visible skip (77) without it.
raytrace_add_suite(test_json_output LIBS raytrace_cli)
add_test(NAME test_json_output_python COMMAND raytrace_test_json_output python
         WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
set_tests_properties(test_json_output_python PROPERTIES SKIP_RETURN_CODE 77
                     TIMEOUT 120)
# What the programs write (tests/test_cli_outputs.c): never over an input,
# rt-convert on the option table, a failed final save that keeps the image.
# `test_cli_outputs_sources` checks the material-library cases once the
# loader lists the files it read; until then it exits 77, a skip.
raytrace_add_suite(test_cli_outputs)
set_tests_properties(test_cli_outputs PROPERTIES TIMEOUT 300)
add_test(NAME test_cli_outputs_sources
         COMMAND raytrace_test_cli_outputs sources
         WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
set_tests_properties(test_cli_outputs_sources PROPERTIES
                     SKIP_RETURN_CODE 77 TIMEOUT 120)
# The ends of a real option's interval, and rt-view's --scale 64
# (tests/test_cli_bounds.c).
raytrace_add_suite(test_cli_bounds
  LIBS raytrace_cli)
set_tests_properties(test_cli_bounds PROPERTIES TIMEOUT 120)
# The progress line (tests/test_progress.c): its fitting to a width, and
# rt-export under a pseudo-terminal of 70 columns and into a file.
raytrace_add_suite(test_progress LIBS raytrace_cli)
set_tests_properties(test_progress PROPERTIES TIMEOUT 300)
