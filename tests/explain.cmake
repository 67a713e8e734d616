# Included from tests/CMakeLists.txt: the ray tree of a pixel and the debug
# views (raytrace/explain.h).  INTERNAL: it compares the explained value with
# the render path's own, through render_internal.h.
raytrace_add_suite(test_explain INTERNAL)
