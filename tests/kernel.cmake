# The fast kernel against the scalar loops.  Included from
# tests/CMakeLists.txt; uses the benchmark's scene generators.
raytrace_add_suite(test_kernel INTERNAL
  SOURCES "${PROJECT_SOURCE_DIR}/bench/bench_scenes.c")
target_include_directories(raytrace_test_kernel PRIVATE
  "${PROJECT_SOURCE_DIR}/bench")
raytrace_add_shared_test(test_kernel)
