# The PLY reader: ASCII and binary bodies against the same OBJ, list types,
# skipped elements, colours, normals, refusals with their places, the
# claimed counts, cancellation, unknown extensions in the programs
# (tests/test_ply.c).  Included from tests/CMakeLists.txt, which defines
# raytrace_add_suite().
raytrace_add_suite(test_ply INTERNAL)
