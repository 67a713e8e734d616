# The octree against brute force.  Included from
# tests/CMakeLists.txt; uses the benchmark's scene generators.  The scenes
# of ../shared get their own entry, skipped (exit 77) when it is absent.
raytrace_add_suite(test_octree INTERNAL
  SOURCES "${PROJECT_SOURCE_DIR}/tools/rt-perf/bench_scenes.c"
          accel_scenes.c)
target_include_directories(raytrace_test_octree PRIVATE
  "${PROJECT_SOURCE_DIR}/tools/rt-perf")
set_tests_properties(test_octree PROPERTIES TIMEOUT 900)
raytrace_add_shared_test(test_octree TIMEOUT 900)

# The octree under hostile geometry: cancelled builds, sliver fans, far
# origins (tests/test_octree_hostile.c).
raytrace_add_suite(test_octree_hostile INTERNAL
  SOURCES "${PROJECT_SOURCE_DIR}/tools/rt-perf/bench_scenes.c")
target_include_directories(raytrace_test_octree_hostile PRIVATE
  "${PROJECT_SOURCE_DIR}/tools/rt-perf")
set_tests_properties(test_octree_hostile PROPERTIES TIMEOUT 900)

# The builds of a load and a render poll their cancellation flag (the
# builder, the kernels).
raytrace_add_suite(test_cancel_builds INTERNAL)
