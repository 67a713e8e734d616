# Install rules: the library, its public headers, the exported CMake package
# (find_package(raytrace) -> raytrace::raytrace) and raytrace.pc.
#
# Included at the end of the top-level CMakeLists.txt when RAYTRACE_INSTALL
# is on (by default only at the top level), after every add_subdirectory, so that other libraries of the project can join the same
# export set with install(TARGETS <lib> EXPORT raytraceTargets ...): this file
# installs that set, once, under the namespace raytrace::.
#
# Layout under the prefix:
#   lib/libraytrace.{a,so*}            include/raytrace/*.h (+ version.h)
#   lib/cmake/raytrace/raytrace{Config,ConfigVersion,Targets*}.cmake
#   lib/pkgconfig/raytrace.pc          (relocatable: paths from ${pcfiledir})
#   share/doc/raytrace/LICENSE         share/man/man1/rt-export.1, rt-convert.1,
#                                      rt-view.1
#   share/raytrace/scenes/            bin/rt-export ... (RAYTRACE_APPS)
include(CMakePackageConfigHelpers)

set(RAYTRACE_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/raytrace"
    CACHE STRING "Where to install raytraceConfig.cmake (relative to the prefix)")
mark_as_advanced(RAYTRACE_INSTALL_CMAKEDIR)

install(TARGETS raytrace EXPORT raytraceTargets
  ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")

# install(DIRECTORY) lists the headers when installing, not when configuring,
# so unlike file(GLOB) it can never miss a header added since.
install(DIRECTORY "${PROJECT_SOURCE_DIR}/include/raytrace"
  DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}"
  FILES_MATCHING PATTERN "*.h")
install(FILES "${PROJECT_BINARY_DIR}/include/raytrace/version.h"
  DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/raytrace")

# The CMake package.
# A static libraytrace built with libpng needs it at link time.
if(RAYTRACE_HAVE_PNG)
  set(RAYTRACE_PC_REQUIRES_PRIVATE "libpng")
  set(RAYTRACE_FIND_PNG "find_dependency(PNG)")
else()
  set(RAYTRACE_PC_REQUIRES_PRIVATE "")
  set(RAYTRACE_FIND_PNG "")
endif()
# And with OpenEXR, its pkg-config target (src/CMakeLists.txt's name).
if(RAYTRACE_HAVE_EXR)
  string(STRIP "${RAYTRACE_PC_REQUIRES_PRIVATE} OpenEXR"
         RAYTRACE_PC_REQUIRES_PRIVATE)
  string(APPEND RAYTRACE_FIND_PNG "\nfind_dependency(PkgConfig)\n"
         "pkg_check_modules(RT_OPENEXR REQUIRED IMPORTED_TARGET OpenEXR)")
endif()
install(EXPORT raytraceTargets
  NAMESPACE raytrace::
  DESTINATION "${RAYTRACE_INSTALL_CMAKEDIR}")
# raytrace::imgsdl, the course's libimgsdl (src/in104/imgsdl), in a file of
# its own: it needs SDL2, which raytraceConfig.cmake looks for only then.
get_property(_rt_imgsdl_exported GLOBAL PROPERTY RAYTRACE_IMGSDL_EXPORTED)
if(_rt_imgsdl_exported)
  install(EXPORT raytraceImgsdlTargets
    NAMESPACE raytrace::
    DESTINATION "${RAYTRACE_INSTALL_CMAKEDIR}")
endif()
configure_package_config_file(
  "${PROJECT_SOURCE_DIR}/cmake/raytraceConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/raytraceConfig.cmake"
  INSTALL_DESTINATION "${RAYTRACE_INSTALL_CMAKEDIR}")
# Compatible versions follow the soname (src/CMakeLists.txt): before 1.0 a
# minor release may break the API and ABI, so find_package(raytrace 0.5)
# takes any 0.5.x and no 0.4 or 0.6; from 1.0 on, the same major version.
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(_rt_compatibility SameMinorVersion)
else()
  set(_rt_compatibility SameMajorVersion)
endif()
write_basic_package_version_file(
  "${PROJECT_BINARY_DIR}/raytraceConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY ${_rt_compatibility})
install(FILES
  "${PROJECT_BINARY_DIR}/raytraceConfig.cmake"
  "${PROJECT_BINARY_DIR}/raytraceConfigVersion.cmake"
  DESTINATION "${RAYTRACE_INSTALL_CMAKEDIR}")

# raytrace.pc (relocatable, cmake/RaytracePkgConfig.cmake).  What a program
# needs after -lraytrace: a shared libraytrace brings libm, threads and
# libpng itself, so they are private; a static one needs them on the link
# line, and `pkg-config --libs` without --static reads only Libs and
# Requires, so there they are public.
if(BUILD_SHARED_LIBS)
  set(RAYTRACE_PC_REQUIRES "")
  set(RAYTRACE_PC_LIBS "")
  set(RAYTRACE_PC_LIBS_PRIVATE "-lm -pthread")
else()
  set(RAYTRACE_PC_REQUIRES "${RAYTRACE_PC_REQUIRES_PRIVATE}")
  set(RAYTRACE_PC_REQUIRES_PRIVATE "")
  set(RAYTRACE_PC_LIBS " -lm -pthread")
  set(RAYTRACE_PC_LIBS_PRIVATE "")
endif()
raytrace_install_pkgconfig(raytrace "${PROJECT_SOURCE_DIR}/cmake/raytrace.pc.in")

# The package: the licence, the programs' manual pages, the scenes.
install(FILES "${PROJECT_SOURCE_DIR}/LICENSE"
  DESTINATION "${CMAKE_INSTALL_DOCDIR}")
if(RAYTRACE_APPS)
  # one page per installed program, installed with it
  foreach(program rt-export rt-convert rt-view rt-export-mpi rt-bench
          in104-render)
    string(REPLACE "-" "_" target "raytrace_${program}")
    if(TARGET ${target})
      install(FILES "${PROJECT_SOURCE_DIR}/man/${program}.1"
        DESTINATION "${CMAKE_INSTALL_MANDIR}/man1")
    endif()
  endforeach()
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/scenes/"
    DESTINATION "${CMAKE_INSTALL_DATADIR}/raytrace/scenes")
endif()
