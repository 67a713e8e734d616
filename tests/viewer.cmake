# test_viewer: the viewer's session and window (apps/viewer), driven without
# an event loop on SDL's dummy video driver (software rendering, no
# display), so it runs headless in CI.
# Only when the viewer is built (RAYTRACE_VIEWER and SDL2, apps/viewer.cmake).
if(TARGET raytrace_viewer)
  raytrace_add_suite(test_viewer LIBS raytrace_viewer)
  # One test compares with the image rt-export writes.
  add_dependencies(test_viewer rt-export)
  target_compile_definitions(test_viewer PRIVATE
    RT_EXPORT_PATH="$<TARGET_FILE:rt-export>")
  set_tests_properties(test_viewer PROPERTIES
    ENVIRONMENT "SDL_VIDEODRIVER=dummy;SDL_AUDIODRIVER=dummy")
endif()
