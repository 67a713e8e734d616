# test_viewer: the viewer's session and window (apps/viewer), driven without
# an event loop on SDL's dummy video driver (software rendering, no
# display), so it runs headless in CI.
# Only when the viewer is built (RAYTRACE_VIEWER and SDL2, apps/viewer.cmake).
if(TARGET raytrace_viewer)
  raytrace_add_suite(test_viewer LIBS raytrace_viewer)
  # One test compares with the image rt-export writes; one runs rt-view
  # without a display.
  add_dependencies(test_viewer rt-export rt-view)
  target_compile_definitions(test_viewer PRIVATE
    RT_EXPORT_PATH="$<TARGET_FILE:rt-export>"
    RT_VIEW_PATH="$<TARGET_FILE:rt-view>")
  set_tests_properties(test_viewer PROPERTIES
    ENVIRONMENT "SDL_VIDEODRIVER=dummy;SDL_AUDIODRIVER=dummy")
endif()
