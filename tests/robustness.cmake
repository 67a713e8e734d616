# Numerical robustness: the stiff and extreme cases of tests/robust/,
# asserted by the Check suite tests/test_robust.c and measured against the
# naive references by robustness-report, which prints the table of
# docs/robustness.md.
add_library(raytrace_robust STATIC
  robust/cases.c
  robust/cases_camera.c
  robust/cases_glass.c
  robust/cases_invariance.c
  robust/cases_shadows.c
  robust/cases_special.c
  robust/cases_watertight.c
  robust/engine.c
  robust/scenes.c)
# The cases use the support library's generator, probe and children.
target_link_libraries(raytrace_robust PUBLIC raytrace_test_support
                      raytrace_internal)
target_include_directories(raytrace_robust PUBLIC
  "${CMAKE_CURRENT_SOURCE_DIR}" "${PROJECT_SOURCE_DIR}/src")
target_compile_definitions(raytrace_robust PRIVATE _POSIX_C_SOURCE=200809L)
raytrace_set_warnings(raytrace_robust)
find_library(RAYTRACE_ROBUST_LIBM m)
if(RAYTRACE_ROBUST_LIBM)
  target_link_libraries(raytrace_robust PUBLIC m)
endif()

add_executable(raytrace_robustness_report robust/robustness_report.c)
set_target_properties(raytrace_robustness_report PROPERTIES
  OUTPUT_NAME robustness-report)
target_link_libraries(raytrace_robustness_report PRIVATE raytrace_robust)
raytrace_set_warnings(raytrace_robustness_report)

# One suite, tests/test_robust.c, a table of groups: each group is a ctest
# entry of its own (test_robust_<group>, label robustness), run with the
# accelerators forced off, then with the octree forced on
# (test_robust_<group>_octree) and with the kd-tree forced on
# (test_robust_<group>_kdtree): the same assertions hold every way.  Without an argument the suite checks
# that every case of robust/cases.c is in one group (test_robust).
raytrace_add_suite(test_robust LIBS raytrace_robust)
foreach(group
    watertight
    facets
    invariance
    shadows
    lights
    camera
    recursion
    special
    determinism
    transparency)
  foreach(accel none octree kdtree)
    set(name test_robust_${group})
    if(NOT accel STREQUAL "none")
      string(APPEND name _${accel})
    endif()
    add_test(NAME ${name} COMMAND raytrace_test_robust ${group}
             WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
    set_tests_properties(${name} PROPERTIES LABELS robustness TIMEOUT 300
                         ENVIRONMENT RT_TEST_ACCEL=${accel})
  endforeach()
endforeach()

# A ground far wider than the eye is high, against exact images from
# tests/reference/stiff_ground.py (python3; without it a visible skip).
raytrace_add_suite(test_stiff_ground)
set_tests_properties(test_stiff_ground PROPERTIES LABELS robustness
                     SKIP_RETURN_CODE 77 TIMEOUT 600)
