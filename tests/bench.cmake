# rt-bench's metrics: built when tools/rt-bench/CMakeLists.txt made the
# raytrace_bench library.
if(TARGET raytrace_bench)
  raytrace_add_suite(test_metrics LIBS raytrace_bench)
endif()
