# rt-view, the SDL2 viewer.
#
# RAYTRACE_VIEWER: AUTO builds it when SDL2 is found, ON requires SDL2, OFF
# skips it.  SDL2 comes from the system: its CMake package (Debian's
# libsdl2-dev installs sdl2-config.cmake) or else pkg-config's sdl2.pc.
# Only rt-view and the viewer's own code link SDL2, never libraytrace.
#
# The viewer's logic is a static library, raytrace_viewer, so that
# tests/viewer.cmake can link it into test_viewer; the SDL2 target is made
# global for the same reason (tests/ is a sibling directory).

string(TOUPPER "${RAYTRACE_VIEWER}" _rt_viewer_mode)
if(NOT _rt_viewer_mode MATCHES "^(AUTO|ON|OFF)$")
  message(FATAL_ERROR
    "RAYTRACE_VIEWER must be AUTO, ON or OFF, not '${RAYTRACE_VIEWER}'")
endif()

set(RAYTRACE_SDL2_TARGET "")
if(NOT _rt_viewer_mode STREQUAL "OFF")
  find_package(SDL2 CONFIG QUIET)
  if(TARGET SDL2::SDL2)
    set(RAYTRACE_SDL2_TARGET SDL2::SDL2)
  elseif(TARGET SDL2::SDL2-static)
    set(RAYTRACE_SDL2_TARGET SDL2::SDL2-static)
  else()
    find_package(PkgConfig QUIET)
    if(PKG_CONFIG_FOUND)
      pkg_check_modules(RAYTRACE_SDL2 QUIET IMPORTED_TARGET GLOBAL sdl2)
      if(RAYTRACE_SDL2_FOUND)
        set(RAYTRACE_SDL2_TARGET PkgConfig::RAYTRACE_SDL2)
      endif()
    endif()
  endif()
  if(RAYTRACE_SDL2_TARGET MATCHES "^SDL2::")
    get_target_property(_rt_sdl2_global ${RAYTRACE_SDL2_TARGET} IMPORTED_GLOBAL)
    if(NOT _rt_sdl2_global)
      set_target_properties(${RAYTRACE_SDL2_TARGET} PROPERTIES
                            IMPORTED_GLOBAL TRUE)
    endif()
  endif()
endif()

set(RAYTRACE_VIEWER_ENABLED OFF)
if(RAYTRACE_SDL2_TARGET)
  set(RAYTRACE_VIEWER_ENABLED ON)
elseif(_rt_viewer_mode STREQUAL "ON")
  message(FATAL_ERROR
    "RAYTRACE_VIEWER=ON but SDL2 was not found (neither its CMake package "
    "nor pkg-config's sdl2).  Install SDL2's development files "
    "(Debian/Ubuntu: apt-get install libsdl2-dev), point SDL2_DIR at "
    "sdl2-config.cmake, or configure with -DRAYTRACE_VIEWER=OFF.")
elseif(_rt_viewer_mode STREQUAL "AUTO" AND RAYTRACE_TOP_LEVEL)
  message(STATUS "viewer disabled: SDL2 not found")
endif()
raytrace_feature_info(rt-view RAYTRACE_VIEWER_ENABLED
  "SDL2 window showing a render as it happens (RAYTRACE_VIEWER=${_rt_viewer_mode})")

if(RAYTRACE_VIEWER_ENABLED)
  find_package(Threads REQUIRED)

  add_library(raytrace_viewer STATIC
    viewer/view_app.c
    viewer/view_explain.c
    viewer/view_load.c
    viewer/view_overlay.c
    viewer/view_scene.c
    viewer/view_session.c
    viewer/view_window.c)
  target_include_directories(raytrace_viewer PUBLIC
    "${CMAKE_CURRENT_SOURCE_DIR}/viewer")
  # raytrace_cli: the rules the programs share (an output is never an
  # input, how a ray tree is read)
  target_link_libraries(raytrace_viewer PUBLIC raytrace::raytrace
    raytrace_cli ${RAYTRACE_SDL2_TARGET} Threads::Threads)
  raytrace_set_warnings(raytrace_viewer)

  # SDL2_ttf, optional: the click overlay's text and the help in the
  # window (Debian: libsdl2-ttf-dev and fonts-dejavu-core).  Without it
  # that text goes to standard output only.
  set(RAYTRACE_VIEWER_TTF_TARGET "")
  find_package(SDL2_ttf CONFIG QUIET)
  if(TARGET SDL2_ttf::SDL2_ttf)
    set(RAYTRACE_VIEWER_TTF_TARGET SDL2_ttf::SDL2_ttf)
  else()
    find_package(PkgConfig QUIET)
    if(PKG_CONFIG_FOUND)
      pkg_check_modules(RAYTRACE_SDL2_TTF QUIET IMPORTED_TARGET SDL2_ttf)
      if(RAYTRACE_SDL2_TTF_FOUND)
        set(RAYTRACE_VIEWER_TTF_TARGET PkgConfig::RAYTRACE_SDL2_TTF)
      endif()
    endif()
  endif()
  set(RAYTRACE_VIEWER_TTF_ENABLED OFF)
  if(RAYTRACE_VIEWER_TTF_TARGET)
    set(RAYTRACE_VIEWER_TTF_ENABLED ON)
    target_link_libraries(raytrace_viewer PRIVATE
      ${RAYTRACE_VIEWER_TTF_TARGET})
    target_compile_definitions(raytrace_viewer PUBLIC RAYTRACE_VIEWER_TTF)
  elseif(RAYTRACE_TOP_LEVEL)
    message(STATUS "rt-view text in the window disabled: SDL2_ttf not found")
  endif()
  raytrace_feature_info(rt-view-text RAYTRACE_VIEWER_TTF_ENABLED
    "rt-view shows the ray tree and its help in the window (SDL2_ttf)")

  raytrace_add_program(rt-view rt-view.c LIBS raytrace_viewer raytrace_cli)
endif()
