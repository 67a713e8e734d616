# Included from tests/CMakeLists.txt: the ray tree of a pixel and the debug
# views (raytrace/explain.h).  INTERNAL: it compares the explained value with
# the render path's own, through render_internal.h.
raytrace_add_suite(test_explain INTERNAL)
# An explanation's terms as the rendering model names them, a total internal
# reflection included, in rt-export's --explain and (when the viewer is
# built) rt-view's click (tests/test_explain_terms.c).
if(TARGET raytrace_viewer)
  raytrace_add_suite(test_explain_terms LIBS raytrace_cli raytrace_viewer)
  target_compile_definitions(raytrace_test_explain_terms PRIVATE
    RT_TEST_HAVE_VIEWER=1)
else()
  raytrace_add_suite(test_explain_terms LIBS raytrace_cli)
  target_compile_definitions(raytrace_test_explain_terms PRIVATE
    RT_TEST_HAVE_VIEWER=0)
endif()
set_tests_properties(test_explain_terms PROPERTIES TIMEOUT 120)
# One formatter: rt-view's text for a clicked pixel is rt-export
# --explain's, byte for byte (tests/test_explain_same.c; SDL's dummy
# driver for the click).
if(TARGET raytrace_viewer)
  raytrace_add_suite(test_explain_same
    LIBS raytrace_viewer)
  set_tests_properties(test_explain_same PROPERTIES TIMEOUT 120
    ENVIRONMENT "SDL_VIDEODRIVER=dummy;SDL_AUDIODRIVER=dummy")
endif()
