# rt-bench's metrics (issue 6): built when apps/rt-bench.cmake made the
# raytrace_bench library.
if(TARGET raytrace_bench)
  raytrace_add_suite(test_metrics LIBS raytrace_bench)
endif()
