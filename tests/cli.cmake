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
