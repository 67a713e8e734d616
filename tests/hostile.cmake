# Bad input and faults, one suite by subject: the loaders fed fuzz findings
# and hostile counts (test_hostile_input), parse time proportional to the
# input (test_hostile_time), failing writes that lose nothing
# (test_hostile_writes), and rt-export and rt-bench interrupted or unable to
# write (test_hostile_export).  What they share is in the support library
# (support/); RT_EXPORT_PATH and RT_BENCH_PATH come from raytrace_add_suite.
foreach(subject input time writes export)
  raytrace_add_suite(test_hostile_${subject})
  set_tests_properties(test_hostile_${subject} PROPERTIES TIMEOUT 900)
endforeach()
