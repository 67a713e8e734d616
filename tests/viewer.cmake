# test_viewer: the viewer's session and window (apps/viewer), driven without
# an event loop on SDL's dummy video driver (software rendering, no
# display), so it runs headless in CI.
# Only when the viewer is built (RAYTRACE_VIEWER and SDL2, apps/viewer.cmake).
if(TARGET raytrace_viewer)
  # One test compares with the image rt-export writes; one runs rt-view
  # without a display (RT_EXPORT_PATH, RT_VIEW_PATH: raytrace_add_suite).
  raytrace_add_suite(test_viewer LIBS raytrace_viewer)
  set_tests_properties(test_viewer PROPERTIES
    ENVIRONMENT "SDL_VIDEODRIVER=dummy;SDL_AUDIODRIVER=dummy")
endif()
