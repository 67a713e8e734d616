# The NFF reader and the tessellation of its spheres, cones and polygons
# tests/test_nff.c.  Included from tests/CMakeLists.txt.  The
# SPD scenes of ../shared/formats are loaded when ../shared is there (the
# test prints that it skipped them otherwise).
raytrace_add_suite(test_nff INTERNAL)
set_tests_properties(test_nff PROPERTIES TIMEOUT 300)
raytrace_add_shared_test(test_nff)
# tests/test_convert_same.c: NFF models written as extended .scn read back
# as the same scene and render the same bytes; the SPD scenes of
# ../shared/formats in their own entry (skipped without ../shared).
raytrace_add_suite(test_convert_same)
set_tests_properties(test_convert_same PROPERTIES TIMEOUT 300)
raytrace_add_shared_test(test_convert_same)
