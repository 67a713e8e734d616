# Bad input and faults (issue 8): fuzz findings, resource bounds, failing
# writes and interrupted runs of rt-export (tests/test_hostile.c).
# (RT_EXPORT_PATH and RT_BENCH_PATH come from raytrace_add_suite.)
raytrace_add_suite(test_hostile)
set_tests_properties(test_hostile PROPERTIES TIMEOUT 900)
