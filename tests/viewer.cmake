# test_viewer: the viewer's session and window (apps/rt-view), driven without
# an event loop on SDL's dummy video driver (software rendering, no
# display), so it runs headless in CI.
# Only when the viewer is built (RAYTRACE_VIEWER and SDL2, apps/rt-view/CMakeLists.txt).
if(TARGET raytrace_viewer)
  # What the viewer's suites share (support/viewer.h), a library of its own:
  # it links raytrace_viewer and SDL2, which the other suites must not load.
  add_library(raytrace_test_viewer_support STATIC support/viewer.c)
  target_link_libraries(raytrace_test_viewer_support PUBLIC
                        raytrace_test_support raytrace_viewer)
  raytrace_set_warnings(raytrace_test_viewer_support)
  # The session and the window (test_viewer), the app (test_viewer_app:
  # one test runs rt-view without a display), the click overlay and debug
  # views (test_viewer_overlay), the passes coarse to fine, the debug views
  # and cameras of a session (test_viewer_progressive).  One test compares
  # with the image rt-export writes (RT_EXPORT_PATH, RT_VIEW_PATH:
  # raytrace_add_suite).
  foreach(family "" _app _overlay _progressive)
    raytrace_add_suite(test_viewer${family} LIBS raytrace_test_viewer_support)
    set_tests_properties(test_viewer${family} PROPERTIES
      ENVIRONMENT "SDL_VIDEODRIVER=dummy;SDL_AUDIODRIVER=dummy")
  endforeach()
  # S never writes over an input (tests/test_viewer_outputs.c); the
  # material-library case, `test_viewer_outputs_sources`, is a skip (77)
  # until the loader lists the files it read.
  raytrace_add_suite(test_viewer_outputs LIBS raytrace_test_viewer_support)
  add_test(NAME test_viewer_outputs_sources
           COMMAND raytrace_test_viewer_outputs sources
           WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
  set_tests_properties(test_viewer_outputs test_viewer_outputs_sources
    PROPERTIES ENVIRONMENT "SDL_VIDEODRIVER=dummy;SDL_AUDIODRIVER=dummy"
    TIMEOUT 120)
  set_tests_properties(test_viewer_outputs_sources PROPERTIES
    SKIP_RETURN_CODE 77)
  # Loads on a worker thread: live window, cancels, quits that never wait.
  raytrace_add_suite(test_viewer_load LIBS raytrace_test_viewer_support)
  set_tests_properties(test_viewer_load PROPERTIES
    ENVIRONMENT "SDL_VIDEODRIVER=dummy;SDL_AUDIODRIVER=dummy")
  # The camera's moves (view_camera.c, view_move.c): the arithmetic, C's
  # text read back bit for bit, and the app's drags, wheel and keys.
  raytrace_add_suite(test_view_camera LIBS raytrace_test_viewer_support)
  set_tests_properties(test_view_camera PROPERTIES
    ENVIRONMENT "SDL_VIDEODRIVER=dummy;SDL_AUDIODRIVER=dummy")
endif()

# The click overlay on a real X server: rt-view under Xvfb, driven by
# xdotool (tests/viewer_xvfb.sh, sharing tests/xvfb_session.sh).  Skipped (77) without Xvfb or xdotool;
# test_viewer checks the same overlay in process, pixel by pixel.
if(TARGET raytrace_rt_view)
  find_program(BASH_PROGRAM bash)
  if(BASH_PROGRAM)
    add_test(NAME viewer_xvfb
      COMMAND "${BASH_PROGRAM}" "${CMAKE_CURRENT_SOURCE_DIR}/viewer_xvfb.sh")
    set_tests_properties(viewer_xvfb PROPERTIES
      ENVIRONMENT "RT_VIEW=$<TARGET_FILE:raytrace_rt_view>;RT_SOURCE_DIR=${PROJECT_SOURCE_DIR}"
      SKIP_RETURN_CODE 77 TIMEOUT 300)
    # The watched scene replaced by a FIFO: the window still answers, and
    # Escape and SIGTERM end it (tests/viewer_xvfb_fifo.sh).
    add_test(NAME viewer_xvfb_fifo
      COMMAND "${BASH_PROGRAM}" "${CMAKE_CURRENT_SOURCE_DIR}/viewer_xvfb_fifo.sh")
    set_tests_properties(viewer_xvfb_fifo PROPERTIES
      ENVIRONMENT "RT_VIEW=$<TARGET_FILE:raytrace_rt_view>;RT_SOURCE_DIR=${PROJECT_SOURCE_DIR}"
      SKIP_RETURN_CODE 77 TIMEOUT 300)
    # A slow scene's picture, then its normal view, rendered off the event
    # loop: N during the render, then Escape, which exits at once
    # (tests/viewer_xvfb_progressive.sh).
    add_test(NAME viewer_xvfb_progressive
      COMMAND "${BASH_PROGRAM}" "${CMAKE_CURRENT_SOURCE_DIR}/viewer_xvfb_progressive.sh")
    set_tests_properties(viewer_xvfb_progressive PROPERTIES
      ENVIRONMENT "RT_VIEW=$<TARGET_FILE:raytrace_rt_view>;RT_SOURCE_DIR=${PROJECT_SOURCE_DIR}"
      SKIP_RETURN_CODE 77 TIMEOUT 300)
    # The camera moved with the mouse: a drag and the wheel change the
    # picture, and C's rt-export options give S's image byte for byte
    # (tests/viewer_xvfb_move.sh).
    add_test(NAME viewer_xvfb_move
      COMMAND "${BASH_PROGRAM}" "${CMAKE_CURRENT_SOURCE_DIR}/viewer_xvfb_move.sh")
    set_tests_properties(viewer_xvfb_move PROPERTIES
      ENVIRONMENT "RT_VIEW=$<TARGET_FILE:raytrace_rt_view>;RT_EXPORT=$<TARGET_FILE:raytrace_rt_export>;RT_SOURCE_DIR=${PROJECT_SOURCE_DIR}"
      SKIP_RETURN_CODE 77 TIMEOUT 300)
    # One X server test at a time: each starts its own Xvfb, and two
    # starting at once under a loaded machine raced for a display.
    set_tests_properties(viewer_xvfb viewer_xvfb_fifo viewer_xvfb_progressive
      viewer_xvfb_move
      PROPERTIES RESOURCE_LOCK xvfb)
  endif()
endif()
