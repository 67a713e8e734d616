# The Wavefront OBJ reader: index forms, triangulation,
# materials, the automatic camera, refusals.  Included from
# tests/CMakeLists.txt, which defines raytrace_add_suite().
raytrace_add_suite(test_obj)
# What the reader gives a render: the automatic camera, the view options,
# renders (tests/test_obj_view.c).
raytrace_add_suite(test_obj_view)
# Models from elsewhere, when RAYTRACE_OBJ_MODELS names a folder of them;
# without it a visible skip (77).
add_test(NAME test_obj_view_models COMMAND raytrace_test_obj_view models
         WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
set_tests_properties(test_obj_view_models PROPERTIES SKIP_RETURN_CODE 77
                     TIMEOUT 600)
# The files an OBJ names: the resolver's rule, the budget, each file read
# once, what is never quoted (tests/test_obj_files.c).
raytrace_add_suite(test_obj_files)
# The readers' polygon triangulator and NFF's calls into it
# (tests/test_triangulate.c).
raytrace_add_suite(test_triangulate INTERNAL)
# The exact cross product that decides which faces have an area: its
# scaling by a power of two is ldexp's, bit for bit (tests/test_exact.c).
raytrace_add_suite(test_exact INTERNAL)
# What hostile OBJ and MTL input costs: bytes in against facets, warnings
# and memory out (tests/test_obj_costs.c).
raytrace_add_suite(test_obj_costs)
set_tests_properties(test_obj_costs PROPERTIES TIMEOUT 600)
# Vertex normals, highlights and the up axis of the mesh readers (OBJ `vn`,
# MTL Ks/Ns/illum, PLY nx/ny/nz, --up-axis; tests/test_mesh_normals.c).
raytrace_add_suite(test_mesh_normals)
# `rt-convert --extended` of OBJ and PLY models renders as the model
# (SPEC section 8; needs the extended .scn records: tests/test_mesh_convert.c).
raytrace_add_suite(test_mesh_convert)
