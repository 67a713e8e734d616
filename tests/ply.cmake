# The PLY reader: ASCII and binary bodies against the same OBJ, list types,
# skipped elements, colours, normals, refusals with their places, the
# claimed counts, cancellation (tests/test_ply.c); names and the programs:
# unknown extensions, rt-convert's .scn, standard input
# (tests/test_ply_programs.c).  Both build their files with
# tests/ply_files.c.  Included from tests/CMakeLists.txt, which defines
# raytrace_add_suite().
raytrace_add_suite(test_ply INTERNAL SOURCES ply_files.c)
raytrace_add_suite(test_ply_programs SOURCES ply_files.c)
