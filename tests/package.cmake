# The Debian package (cmake/Packaging.cmake): `cpack -G DEB` builds a .deb
# that holds the library, the headers, the CMake and pkg-config files, the
# programs, the manual pages and the scenes, and whose rt-export, extracted
# into a temporary root, renders a scene extracted with it.
#
# This one file is both halves: included from tests/CMakeLists.txt it
# registers the test (label `package`); run with `cmake -P` it is the test.
# Without cpack or dpkg-deb the test is a visible skip, its reason on its
# output (a line "PACKAGE-SKIP: ...", CTest's SKIP_REGULAR_EXPRESSION).
if(NOT CMAKE_SCRIPT_MODE_FILE)
  # CPackConfig.cmake is written at the end of the top-level configure, after
  # this file is read: register on the condition that includes Packaging.cmake.
  if(TARGET raytrace_rt_export AND RAYTRACE_INSTALL AND RAYTRACE_TOP_LEVEL)
    add_test(NAME package_deb_holds_and_runs
      COMMAND "${CMAKE_COMMAND}"
              "-DCPACK=${CMAKE_CPACK_COMMAND}"
              "-DBINARY_DIR=${PROJECT_BINARY_DIR}"
              "-DWORK=${CMAKE_CURRENT_BINARY_DIR}/package-test"
              "-DVERSION=${PROJECT_VERSION}"
              "-DSHARED=${BUILD_SHARED_LIBS}"
              -P "${CMAKE_CURRENT_LIST_FILE}")
    set_tests_properties(package_deb_holds_and_runs PROPERTIES
      LABELS package SKIP_REGULAR_EXPRESSION "PACKAGE-SKIP: " TIMEOUT 900
      # cpack installs the build tree into its own staging directory.
      RUN_SERIAL ON)
  endif()
  return()
endif()

function(fail)
  message(FATAL_ERROR "package: " ${ARGN})
endfunction()

find_program(DPKG_DEB dpkg-deb)
if(NOT CPACK OR NOT EXISTS "${CPACK}")
  message("PACKAGE-SKIP: cpack not found")
  return()
endif()
if(NOT DPKG_DEB)
  message("PACKAGE-SKIP: dpkg-deb not found (Debian: dpkg): no .deb can be read")
  return()
endif()

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND "${CPACK}" -G DEB -B "${WORK}"
                        --config "${BINARY_DIR}/CPackConfig.cmake"
  WORKING_DIRECTORY "${BINARY_DIR}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  fail("cpack -G DEB failed (${rc}):\n${out}")
endif()
file(GLOB debs "${WORK}/*.deb")
list(LENGTH debs n)
if(NOT n EQUAL 1)
  fail("expected one .deb in ${WORK}, found ${n}: ${debs}\n${out}")
endif()
message("package: ${debs}")

# The control fields.
execute_process(COMMAND "${DPKG_DEB}" -f "${debs}" Package Version Depends
  RESULT_VARIABLE rc OUTPUT_VARIABLE info ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  fail("dpkg-deb -f: ${err}")
endif()
message("${info}")
if(NOT info MATCHES "Package: raytrace\n")
  fail("the package is not named raytrace:\n${info}")
endif()
if(NOT info MATCHES "Version: ${VERSION}\n")
  fail("the package's version is not ${VERSION}:\n${info}")
endif()
find_program(SHLIBDEPS dpkg-shlibdeps)
if(SHLIBDEPS AND NOT info MATCHES "Depends: [^\n]*libc6")
  fail("dpkg-shlibdeps is here, yet the package depends on no libc6:\n${info}")
endif()

# The contents: every kind of file, under /usr.
execute_process(COMMAND "${DPKG_DEB}" -c "${debs}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE listing ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  fail("dpkg-deb -c: ${err}")
endif()
if(SHARED)
  set(library "\\./usr/lib[^ \n]*/libraytrace\\.so")
else()
  set(library "\\./usr/lib[^ \n]*/libraytrace\\.a\n")
endif()
foreach(pattern
    "${library}"
    "\\./usr/include/raytrace/raytrace\\.h\n"
    "\\./usr/include/raytrace/version\\.h\n"
    "\\./usr/lib[^ \n]*/pkgconfig/raytrace\\.pc\n"
    "\\./usr/lib[^ \n]*/cmake/raytrace/raytraceConfig\\.cmake\n"
    "\\./usr/bin/rt-export\n"
    "\\./usr/bin/rt-convert\n"
    "\\./usr/share/man/man1/rt-export\\.1"
    "\\./usr/share/man/man1/rt-convert\\.1"
    "\\./usr/share/raytrace/scenes/cubes\\.scn\n"
    "\\./usr/share/raytrace/scenes/teapot\\.scn\n")
  if(NOT listing MATCHES "${pattern}")
    fail("no file matching ${pattern} in the package:\n${listing}")
  endif()
endforeach()
# rt-export-mpi cannot start without Open MPI's launcher (openmpi-bin).
if(listing MATCHES "\\./usr/bin/rt-export-mpi\n" AND
   NOT info MATCHES "Depends: [^\n]*openmpi-bin")
  fail("rt-export-mpi is in the package, but it does not depend on openmpi-bin:\n${info}")
endif()
if(listing MATCHES " \\./(usr/local|home|work|tmp)/")
  fail("the package holds files outside /usr:\n${listing}")
endif()

# Extracted into a root of its own, its rt-export renders its scene.
set(root "${WORK}/root")
execute_process(COMMAND "${DPKG_DEB}" -x "${debs}" "${root}"
  RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  fail("dpkg-deb -x: ${err}")
endif()
set(image "${WORK}/cubes.ppm")
execute_process(
  COMMAND "${CMAKE_COMMAND}" -E env "LD_LIBRARY_PATH=${root}/usr/lib"
          "${root}/usr/bin/rt-export" "${root}/usr/share/raytrace/scenes/cubes.scn"
          -o "${image}" --size 40x30 -q
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  fail("the extracted rt-export failed (${rc}): ${out}${err}")
endif()
# A binary PPM of 40 x 30: its 13-byte header, and 3 bytes a pixel after it.
file(READ "${image}" head LIMIT 15)
file(SIZE "${image}" size)
if(NOT head MATCHES "^P6\n40 30\n255\n" OR NOT size EQUAL 3613)
  fail("the extracted rt-export wrote no 40 x 30 PPM (${size} bytes): ${head}")
endif()
message("package: the extracted rt-export rendered ${image}")

# Every extracted program answers --version with the package's version.
string(REGEX MATCHALL "\\./usr/bin/[^\n]+" programs "${listing}")
foreach(entry IN LISTS programs)
  string(REGEX REPLACE "^\\./usr/bin/" "" name "${entry}")
  if(name STREQUAL "")
    continue()
  endif()
  execute_process(
    COMMAND "${CMAKE_COMMAND}" -E env "LD_LIBRARY_PATH=${root}/usr/lib"
            "${root}/usr/bin/${name}" --version
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "^${name} \\(libraytrace\\) ${VERSION}\n")
    fail("the extracted ${name} --version gave ${rc}: ${out}${err}")
  endif()
  message("package: ${out}")
endforeach()
