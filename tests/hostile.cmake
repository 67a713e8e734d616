# Bad input and faults (issue 8): fuzz findings, resource bounds, failing
# writes and interrupted runs of rt-export (tests/test_hostile.c).
raytrace_add_suite(test_hostile)
target_compile_definitions(test_hostile PRIVATE
  RT_EXPORT_PATH="$<TARGET_FILE:rt-export>")
add_dependencies(test_hostile rt-export)
if(TARGET rt-bench)
  target_compile_definitions(test_hostile PRIVATE
    RT_BENCH_PATH="$<TARGET_FILE:rt-bench>")
  add_dependencies(test_hostile rt-bench)
endif()
set_tests_properties(test_hostile PROPERTIES TIMEOUT 900)
