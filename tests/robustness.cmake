# Numerical robustness (issue 5): the stiff and extreme cases of
# tests/robust/, asserted by one Check suite per group (tests/test_robust_*.c)
# and measured against the naive references by robustness-report, which
# prints the table of docs/robustness.md.
add_library(raytrace_robust STATIC
  robust/cases.c
  robust/engine.c
  robust/scenes.c)
target_link_libraries(raytrace_robust PUBLIC raytrace::raytrace)
target_include_directories(raytrace_robust PUBLIC
  "${CMAKE_CURRENT_SOURCE_DIR}" "${PROJECT_SOURCE_DIR}/src")
target_compile_definitions(raytrace_robust PRIVATE _POSIX_C_SOURCE=200809L)
raytrace_set_warnings(raytrace_robust)
find_library(RAYTRACE_ROBUST_LIBM m)
if(RAYTRACE_ROBUST_LIBM)
  target_link_libraries(raytrace_robust PUBLIC m)
endif()

add_executable(robustness-report robust/robustness_report.c)
target_link_libraries(robustness-report PRIVATE raytrace_robust)
raytrace_set_warnings(robustness-report)

foreach(suite
    test_robust_watertight
    test_robust_facets
    test_robust_invariance
    test_robust_shadows
    test_robust_lights
    test_robust_camera
    test_robust_recursion
    test_robust_special
    test_robust_determinism)
  raytrace_add_suite(${suite} LIBS raytrace_robust)
  # Every case with the octree forced off, and again forced on (issue 12):
  # the same assertions hold either way.
  set_tests_properties(${suite} PROPERTIES LABELS robustness TIMEOUT 300
                       ENVIRONMENT RT_TEST_ACCEL=none)
  add_test(NAME ${suite}_octree COMMAND ${suite}
           WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
  set_tests_properties(${suite}_octree PROPERTIES LABELS robustness
                       TIMEOUT 300 ENVIRONMENT RT_TEST_ACCEL=octree)
endforeach()
