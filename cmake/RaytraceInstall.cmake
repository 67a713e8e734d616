# Install rules: the library, its public headers, the exported CMake package
# (find_package(raytrace) -> raytrace::raytrace) and raytrace.pc.
#
# Included at the end of the top-level CMakeLists.txt, after every
# add_subdirectory, so that other libraries of the project can join the same
# export set with install(TARGETS <lib> EXPORT raytraceTargets ...): this file
# installs that set, once, under the namespace raytrace::.
#
# Layout under the prefix:
#   lib/libraytrace.{a,so*}            include/raytrace/*.h (+ version.h)
#   lib/cmake/raytrace/raytrace{Config,ConfigVersion,Targets*}.cmake
#   lib/pkgconfig/raytrace.pc          (relocatable: paths from ${pcfiledir})
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
write_basic_package_version_file(
  "${PROJECT_BINARY_DIR}/raytraceConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMajorVersion)
install(FILES
  "${PROJECT_BINARY_DIR}/raytraceConfig.cmake"
  "${PROJECT_BINARY_DIR}/raytraceConfigVersion.cmake"
  DESTINATION "${RAYTRACE_INSTALL_CMAKEDIR}")

# raytrace.pc finds the prefix from its own place (${pcfiledir}), so that a
# tree installed with `cmake --install build --prefix DIR`, or moved, still
# works.  Absolute install directories are written as they are.
set(RAYTRACE_PC_DIR "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
if(IS_ABSOLUTE "${RAYTRACE_PC_DIR}")
  set(RAYTRACE_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH RAYTRACE_PC_UP "/prefix/${RAYTRACE_PC_DIR}" "/prefix")
  string(REGEX REPLACE "/$" "" RAYTRACE_PC_UP "${RAYTRACE_PC_UP}")
  set(RAYTRACE_PC_PREFIX "\${pcfiledir}/${RAYTRACE_PC_UP}")
endif()
foreach(dir LIBDIR INCLUDEDIR)
  if(IS_ABSOLUTE "${CMAKE_INSTALL_${dir}}")
    set(RAYTRACE_PC_${dir} "${CMAKE_INSTALL_${dir}}")
  else()
    set(RAYTRACE_PC_${dir} "\${prefix}/${CMAKE_INSTALL_${dir}}")
  endif()
endforeach()
configure_file("${PROJECT_SOURCE_DIR}/cmake/raytrace.pc.in"
               "${PROJECT_BINARY_DIR}/raytrace.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/raytrace.pc"
  DESTINATION "${RAYTRACE_PC_DIR}")
