# The Wavefront OBJ reader: index forms, triangulation,
# materials, the automatic camera, refusals.  Included from
# tests/CMakeLists.txt, which defines raytrace_add_suite().
raytrace_add_suite(test_obj)
