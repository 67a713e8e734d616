# The fast kernel against the scalar loops (issue 7).  Included from
# tests/CMakeLists.txt; uses the benchmark's scene generators.
raytrace_add_suite(test_kernel
  SOURCES "${PROJECT_SOURCE_DIR}/bench/bench_scenes.c")
target_include_directories(test_kernel PRIVATE "${PROJECT_SOURCE_DIR}/bench")
find_library(RAYTRACE_KERNEL_TEST_LIBM m)
if(RAYTRACE_KERNEL_TEST_LIBM)
  target_link_libraries(test_kernel PRIVATE ${RAYTRACE_KERNEL_TEST_LIBM})
endif()
raytrace_add_shared_test(test_kernel)
