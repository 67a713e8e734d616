# CPack: a Debian package of the whole installation (`cd build && cpack -G
# DEB`), and a .tar.gz of the same files (`cpack -G TGZ`).
#
# Included from the top-level CMakeLists.txt after RaytraceInstall.cmake,
# only when the project is top level and installs (a parent project packages
# itself).  The package holds what `cmake --install` installs, under /usr:
#   /usr/lib/libraytrace.a (or .so.*), /usr/include/raytrace/*.h,
#   /usr/lib/cmake/raytrace/, /usr/lib/pkgconfig/raytrace.pc,
#   /usr/bin/rt-export ... (the programs), /usr/share/man/man1/*.1,
#   /usr/share/raytrace/scenes/, /usr/share/doc/raytrace/LICENSE.
# Its dependencies are computed by dpkg-shlibdeps from the programs and the
# shared library (libc6, libpng16-16, libsdl2 when rt-view is built); without
# dpkg-shlibdeps (not a Debian system) the package lists none.
# docs/packaging.md describes it.
set(CPACK_PACKAGE_NAME "raytrace")
set(CPACK_PACKAGE_VENDOR "The libraytrace authors")
set(CPACK_PACKAGE_CONTACT "libraytrace maintainers <raytrace@localhost>")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
  "libraytrace renders scenes of triangles (the course's .scn, NFF, Wavefront OBJ and Stanford PLY) with a Whitted ray tracer: reflections, refraction, several lights, smooth shading and depth of field. The package holds the library and its headers (with CMake and pkg-config files), the programs rt-export, rt-convert and the others, their manual pages and the example scenes (/usr/share/raytrace/scenes).")
set(CPACK_RESOURCE_FILE_LICENSE "${PROJECT_SOURCE_DIR}/LICENSE")
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(CPACK_GENERATOR "DEB")
set(CPACK_SOURCE_GENERATOR "TGZ")
set(CPACK_SOURCE_IGNORE_FILES "/\\\\.git/" "/build/" "/build-.*/")

set(CPACK_DEBIAN_PACKAGE_NAME "raytrace")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION "graphics")
set(CPACK_DEBIAN_PACKAGE_PRIORITY "optional")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${CPACK_PACKAGE_CONTACT}")
find_program(RAYTRACE_DPKG_SHLIBDEPS dpkg-shlibdeps)
mark_as_advanced(RAYTRACE_DPKG_SHLIBDEPS)
if(RAYTRACE_DPKG_SHLIBDEPS)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
endif()
# A static libraytrace built with libpng needs libpng's headers to link.
if(RAYTRACE_HAVE_PNG AND NOT BUILD_SHARED_LIBS)
  set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libpng-dev")
endif()
# rt-export-mpi links libopenmpi3 (a Depends from dpkg-shlibdeps), but Open
# MPI starts no rank, not even a lone one, without its launcher (orted, in
# openmpi-bin): a dependency too (CPack adds dpkg-shlibdeps' list to it).
# A Recommends would not do: `apt-get -f install` after `dpkg -i` skips them.
if(TARGET raytrace_rt_export_mpi)
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "openmpi-bin")
endif()

include(CPack)
