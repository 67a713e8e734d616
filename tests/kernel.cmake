# The fast kernel against the scalar loops.  Included from
# tests/CMakeLists.txt; uses the benchmark's scene generators.
raytrace_add_suite(test_kernel INTERNAL
  SOURCES "${PROJECT_SOURCE_DIR}/tools/rt-perf/bench_scenes.c")
target_include_directories(raytrace_test_kernel PRIVATE
  "${PROJECT_SOURCE_DIR}/tools/rt-perf")
raytrace_add_shared_test(test_kernel)

# The camera-ray packets (src/kernel/packet_impl.h) against the scalar
# loops: scenes built in memory (support/spec.h) to stress the tile and
# shadow culls; the exact geometry (grids, telephoto, a far eye) in
# test_packets_edges.
raytrace_add_suite(test_packets INTERNAL)
raytrace_add_suite(test_packets_edges INTERNAL)

# The shadow rays' last-blocker cache (src/kernel/shade_impl.h), counted
# exactly by brute force, the octree and the kd-tree.
raytrace_add_suite(test_shadow_cache INTERNAL)

# What a render prepares once and reuses: the scene's eye, the team of
# threads (src/base/workers.c), the statistics generated from RT_STATS_MAP.
raytrace_add_suite(test_prepared INTERNAL)

# The kd-tree against brute force (tests/test_kdtree.c): the octree's
# scenes and checks (accel_scenes.c) through the kd-tree, and its own
# bounds.  The scenes of ../shared get their own entry, skipped (exit 77)
# when it is absent.
raytrace_add_suite(test_kdtree INTERNAL
  SOURCES "${PROJECT_SOURCE_DIR}/tools/rt-perf/bench_scenes.c"
          accel_scenes.c)
target_include_directories(raytrace_test_kdtree PRIVATE
  "${PROJECT_SOURCE_DIR}/tools/rt-perf")
set_tests_properties(test_kdtree PROPERTIES TIMEOUT 900)
raytrace_add_shared_test(test_kdtree TIMEOUT 900)
