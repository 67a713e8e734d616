# steps.cmake - the steps of the consumer tests (tests/consumer.cmake), run
# as `cmake -DSTEP=<step> -D... -P steps.cmake`:
#
#   install     cmake --install the build tree into WORK_DIR/prefix (fresh)
#   build       configure and build this directory (consumer.c, example.c)
#               against that prefix with find_package(raytrace)
#   run         run WORK_DIR/build/consumer
#   pkg-config  compile consumer.c and example.c with the plain
#               `cc $(pkg-config --cflags --libs raytrace)` (no --static),
#               run them
#   subdirectory, fetchcontent
#               configure tests/consumer/parent, a project that embeds this
#               source tree that way, with no build type; build it, run its
#               tests, install it; check that nothing of libraytrace shows
#               (its messages, tests, programs, installed files, a build type)
#   shared-install
#               build this source tree with BUILD_SHARED_LIBS=ON (tests,
#               benchmark and SDL2 off), install it into WORK_DIR, move the
#               prefix
#   shared-run  run the moved prefix's bin/rt-export, no LD_LIBRARY_PATH
#   shared-symbols
#               `nm -D --defined-only` of its libraytrace.so lists only the
#               public rt_ API (no rt__ internals, nothing else); skipped
#               ("CONSUMER-SKIP: ...") while the headers have no RT_API
#   shared-pkg-config
#               compile example.c against it with the plain pkg-config line
#   readme      check that the ```c block after the line
#               "<!-- example: tests/consumer/example.c -->" in README.md is
#               byte-identical to example.c
#   example     run WORK_DIR/build/example on scenes/one-facet.scn, check the
#               P6 it writes
#
# Inputs: SOURCE_DIR, BINARY_DIR (of libraytrace), LIBDIR (its
# CMAKE_INSTALL_LIBDIR), WORK_DIR, CONFIG, GENERATOR, C_COMPILER, PKG_CONFIG,
# NM.
cmake_minimum_required(VERSION 3.20)

set(prefix "${WORK_DIR}/prefix")
set(consumer_build "${WORK_DIR}/build")

# Runs a command; on failure prints what ran, its output, and fails.
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result
                  OUTPUT_VARIABLE output ERROR_VARIABLE output)
  message("${output}")
  if(NOT result EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "${what} failed (${result}): ${command}")
  endif()
endfunction()

# A shared libraytrace is found at run time in the prefix.
set(ENV{LD_LIBRARY_PATH} "${prefix}/${LIBDIR}:$ENV{LD_LIBRARY_PATH}")

# The shared build's prefix (the shared-* steps).
set(shared_prefix "${WORK_DIR}/shared-prefix")

# Compiles consumer.c and example.c into DIR with the flags of the plain
# `pkg-config --cflags --libs raytrace` (no --static) of the install in
# PREFIX: what a user types, `cc app.c $(pkg-config --cflags --libs raytrace)`.
function(pkg_config_build prefix dir)
  set(ENV{PKG_CONFIG_PATH} "${prefix}/${LIBDIR}/pkgconfig")
  execute_process(COMMAND "${PKG_CONFIG}" --modversion raytrace
                  OUTPUT_VARIABLE version OUTPUT_STRIP_TRAILING_WHITESPACE
                  RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "pkg-config does not find raytrace.pc in ${prefix}")
  endif()
  execute_process(COMMAND "${PKG_CONFIG}" --cflags --libs raytrace
                  OUTPUT_VARIABLE flags OUTPUT_STRIP_TRAILING_WHITESPACE
                  COMMAND_ERROR_IS_FATAL ANY)
  message("raytrace.pc ${version}: ${flags}")
  separate_arguments(flags UNIX_COMMAND "${flags}")
  file(REMOVE_RECURSE "${dir}")
  file(MAKE_DIRECTORY "${dir}")
  foreach(program consumer example)
    run("compiling ${program}.c with pkg-config's flags" "${C_COMPILER}"
        -std=c11 -Wall -Wextra -Wpedantic -Werror
        "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/${program}.c"
        -o "${dir}/${program}" ${flags})
  endforeach()
endfunction()

if(STEP STREQUAL "install")
  file(REMOVE_RECURSE "${prefix}")
  set(config_args)
  if(CONFIG)
    set(config_args --config "${CONFIG}")
  endif()
  run("cmake --install" "${CMAKE_COMMAND}" --install "${BINARY_DIR}"
      --prefix "${prefix}" ${config_args})
  foreach(file include/raytrace/raytrace.h include/raytrace/version.h)
    if(NOT EXISTS "${prefix}/${file}")
      message(FATAL_ERROR "install did not put ${file} in ${prefix}")
    endif()
  endforeach()

elseif(STEP STREQUAL "build")
  file(REMOVE_RECURSE "${consumer_build}")
  set(type_args)
  if(CONFIG)
    set(type_args "-DCMAKE_BUILD_TYPE=${CONFIG}")
  endif()
  run("configuring the consumer" "${CMAKE_COMMAND}"
      -S "${CMAKE_CURRENT_LIST_DIR}" -B "${consumer_build}"
      -G "${GENERATOR}" "-DCMAKE_C_COMPILER=${C_COMPILER}"
      "-DCMAKE_PREFIX_PATH=${prefix}" ${type_args})
  set(config_args)
  if(CONFIG)
    set(config_args --config "${CONFIG}")
  endif()
  run("building the consumer" "${CMAKE_COMMAND}" --build "${consumer_build}"
      ${config_args})

elseif(STEP STREQUAL "run")
  find_program(consumer consumer PATHS "${consumer_build}"
               PATH_SUFFIXES "${CONFIG}" NO_DEFAULT_PATH REQUIRED)
  run("the consumer" "${consumer}")

elseif(STEP STREQUAL "pkg-config")
  pkg_config_build("${prefix}" "${WORK_DIR}/pkg-config")
  run("the pkg-config consumer" "${WORK_DIR}/pkg-config/consumer")
  run("the pkg-config example" "${WORK_DIR}/pkg-config/example"
      "${SOURCE_DIR}/scenes/one-facet.scn" "${WORK_DIR}/pkg-config/one.ppm")

elseif(STEP STREQUAL "subdirectory" OR STEP STREQUAL "fetchcontent")
  set(parent "${WORK_DIR}/parent-${STEP}")
  file(REMOVE_RECURSE "${parent}")
  # No CMAKE_BUILD_TYPE: libraytrace must not put one in the parent's cache.
  execute_process(COMMAND "${CMAKE_COMMAND}" -S "${CMAKE_CURRENT_LIST_DIR}/parent"
                  -B "${parent}/build" -G "${GENERATOR}"
                  "-DCMAKE_C_COMPILER=${C_COMPILER}" "-DRAYTRACE_MODE=${STEP}"
                  "-DRAYTRACE_SOURCE_DIR=${SOURCE_DIR}"
                  RESULT_VARIABLE result OUTPUT_VARIABLE output
                  ERROR_VARIABLE output)
  message("${output}")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "configuring the parent project failed (${result})")
  endif()
  # libraytrace says nothing in a parent's configure: no feature summary, no
  # "tests disabled", no warning.
  string(REGEX MATCH "[^\n]*(features have been|disabled|enabled|check\\.pc|[Ww]arning|CMake Deprecation)[^\n]*"
         noise "${output}")
  if(noise)
    message(FATAL_ERROR "the parent's configure printed libraytrace's: ${noise}")
  endif()
  file(STRINGS "${parent}/build/CMakeCache.txt" build_type
       REGEX "^CMAKE_BUILD_TYPE:")
  if(NOT build_type MATCHES "^CMAKE_BUILD_TYPE:[A-Z]*=$")
    message(FATAL_ERROR "the parent's cache has ${build_type}; it must stay empty")
  endif()
  file(STRINGS "${parent}/build/CMakeCache.txt" shared REGEX "^BUILD_SHARED_LIBS:")
  if(shared)
    message(FATAL_ERROR "libraytrace set ${shared} in the parent's cache")
  endif()
  run("building the parent project" "${CMAKE_COMMAND}" --build "${parent}/build")
  # Only the libraries: no program, test suite or benchmark of libraytrace,
  # and no libimgsdl, which the parent turned off.
  file(GLOB_RECURSE built LIST_DIRECTORIES false RELATIVE "${parent}/build"
       "${parent}/build/*rt-export*" "${parent}/build/*rt-view*"
       "${parent}/build/*rt-bench*" "${parent}/build/*rt-perf*"
       "${parent}/build/*in104-render*" "${parent}/build/raytrace/*test_*"
       "${parent}/build/*raytrace-imgsdl*")
  list(FILTER built EXCLUDE REGEX "CMakeFiles/")
  if(built)
    message(FATAL_ERROR "the parent's build made libraytrace's programs, "
            "tests or libimgsdl: ${built}")
  endif()
  execute_process(COMMAND "${CMAKE_CTEST_COMMAND}" -N
                  WORKING_DIRECTORY "${parent}/build" OUTPUT_VARIABLE tests)
  message("${tests}")
  string(REGEX MATCHALL "Test +#[0-9]+: [^\n]*" listed "${tests}")
  list(LENGTH listed count)
  if(NOT count EQUAL 2 OR NOT tests MATCHES "parent_renders_a_scene"
     OR NOT tests MATCHES "parent_course_program_gets_the_spec_results")
    message(FATAL_ERROR "the parent's ctest must list its two tests only")
  endif()
  execute_process(COMMAND "${CMAKE_CTEST_COMMAND}" --output-on-failure
                  WORKING_DIRECTORY "${parent}/build" RESULT_VARIABLE result
                  OUTPUT_VARIABLE output ERROR_VARIABLE output)
  message("${output}")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "the parent's tests failed")
  endif()
  run("installing the parent project" "${CMAKE_COMMAND}" --install
      "${parent}/build" --prefix "${parent}/prefix")
  file(GLOB_RECURSE installed RELATIVE "${parent}/prefix" "${parent}/prefix/*")
  list(SORT installed)
  if(NOT installed STREQUAL "bin/course;bin/test_parse")
    message(FATAL_ERROR "the parent's install must install its two programs "
            "only, not: ${installed}")
  endif()

elseif(STEP STREQUAL "shared-install")
  set(build "${WORK_DIR}/shared-build")
  file(REMOVE_RECURSE "${build}" "${shared_prefix}" "${shared_prefix}-first")
  run("configuring a shared build" "${CMAKE_COMMAND}" -S "${SOURCE_DIR}"
      -B "${build}" -G "${GENERATOR}" "-DCMAKE_C_COMPILER=${C_COMPILER}"
      -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=ON -DRAYTRACE_TESTS=OFF
      -DRAYTRACE_BENCH=OFF -DRAYTRACE_VIEWER=OFF -DRAYTRACE_IMGSDL=OFF
      -DRAYTRACE_MPI=OFF)
  run("building the shared build" "${CMAKE_COMMAND}" --build "${build}"
      --parallel 2)
  # Installed in one place, then moved: the programs must find the
  # libraries from wherever the prefix is.
  run("installing the shared build" "${CMAKE_COMMAND}" --install "${build}"
      --prefix "${shared_prefix}-first")
  file(RENAME "${shared_prefix}-first" "${shared_prefix}")

elseif(STEP STREQUAL "shared-run")
  unset(ENV{LD_LIBRARY_PATH})
  set(image "${WORK_DIR}/shared-one-facet.ppm")
  file(REMOVE "${image}")
  run("the installed rt-export of a shared build"
      "${shared_prefix}/bin/rt-export" "${SOURCE_DIR}/scenes/one-facet.scn"
      -o "${image}" --quiet)
  if(NOT EXISTS "${image}")
    message(FATAL_ERROR "rt-export did not write ${image}")
  endif()
  run("the installed in104-render of a shared build"
      "${shared_prefix}/bin/in104-render" "${SOURCE_DIR}/scenes/one-facet.scn"
      "${WORK_DIR}/shared-in104.ppm")

elseif(STEP STREQUAL "shared-symbols")
  # Until the headers mark the public API with RT_API (hidden visibility for
  # the rest), the rule cannot hold: a visible skip, not a failure.
  file(GLOB headers "${SOURCE_DIR}/include/raytrace/*.h")
  set(export_macro OFF)
  foreach(header IN LISTS headers)
    file(STRINGS "${header}" defines REGEX "#[ \t]*define[ \t]+RT_API")
    if(defines)
      set(export_macro ON)
    endif()
  endforeach()
  if(NOT export_macro)
    message("CONSUMER-SKIP: include/raytrace defines no RT_API export macro")
    return()
  endif()
  file(GLOB library "${shared_prefix}/${LIBDIR}/libraytrace.so")
  if(NOT library OR NOT NM)
    message(FATAL_ERROR "no libraytrace.so in ${shared_prefix}/${LIBDIR}, or no nm")
  endif()
  execute_process(COMMAND "${NM}" -D --defined-only "${library}"
                  OUTPUT_VARIABLE symbols COMMAND_ERROR_IS_FATAL ANY)
  string(REGEX MATCHALL "[^\n]+" lines "${symbols}")
  set(foreign)
  set(count 0)
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^.* " "" name "${line}")
    # The linker's own markers are not the library's.
    if(name MATCHES "^(_init|_fini|_edata|_end|__bss_start)$")
      continue()
    endif()
    math(EXPR count "${count} + 1")
    if(NOT name MATCHES "^rt_[a-z0-9]")
      list(APPEND foreign "${name}")
    endif()
  endforeach()
  if(foreign)
    string(REPLACE ";" " " foreign "${foreign}")
    message(FATAL_ERROR "libraytrace.so exports names outside the public rt_ "
            "API: ${foreign}")
  endif()
  message("libraytrace.so exports ${count} names, all of the public rt_ API")

elseif(STEP STREQUAL "shared-pkg-config")
  pkg_config_build("${shared_prefix}" "${WORK_DIR}/shared-pkg-config")
  set(ENV{LD_LIBRARY_PATH} "${shared_prefix}/${LIBDIR}")
  run("the pkg-config example, shared" "${WORK_DIR}/shared-pkg-config/example"
      "${SOURCE_DIR}/scenes/one-facet.scn" "${WORK_DIR}/shared-pkg-config/one.ppm")

elseif(STEP STREQUAL "readme")
  set(readme "${SOURCE_DIR}/README.md")
  set(marker "<!-- example: tests/consumer/example.c -->\n")
  if(NOT EXISTS "${readme}")
    message(FATAL_ERROR "${readme} does not exist")
  endif()
  file(READ "${readme}" text)
  string(FIND "${text}" "${marker}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "README.md has no line \"${marker}\"")
  endif()
  string(LENGTH "${marker}" length)
  math(EXPR at "${at} + ${length}")
  string(SUBSTRING "${text}" ${at} -1 text)
  string(FIND "${text}" "```c\n" open)
  string(FIND "${text}" "\n```" close)
  if(NOT open EQUAL 0 OR close EQUAL -1)
    message(FATAL_ERROR "README.md: the line after \"${marker}\" must open "
            "a ```c block, closed by a line ```")
  endif()
  math(EXPR length "${close} + 1 - 5")
  string(SUBSTRING "${text}" 5 ${length} block)
  set(extracted "${WORK_DIR}/readme-example.c")
  file(WRITE "${extracted}" "${block}")
  execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${extracted}"
                  "${CMAKE_CURRENT_LIST_DIR}/example.c" RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "README.md's example differs from "
            "tests/consumer/example.c; see\n"
            "  diff -u ${extracted} ${CMAKE_CURRENT_LIST_DIR}/example.c")
  endif()
  message("README.md's example is tests/consumer/example.c")

elseif(STEP STREQUAL "example")
  find_program(example example PATHS "${consumer_build}"
               PATH_SUFFIXES "${CONFIG}" NO_DEFAULT_PATH REQUIRED)
  set(scene "${SOURCE_DIR}/scenes/one-facet.scn")
  if(NOT EXISTS "${scene}")
    set(scene "${WORK_DIR}/one-facet.scn")
    file(WRITE "${scene}" "0 0 10\n0 0 5  4 0 5  64 48\n"
         "3\n-6 -4 0\n6 -4 0\n0 5 0\n1\n1 2 3 0.5 200 100 50\n"
         "20 40 60\n0.125 0.125 4 255 204 102\n")
  endif()
  set(image "${WORK_DIR}/example.ppm")
  file(REMOVE "${image}")
  run("the README's example" "${example}" "${scene}" "${image}")
  file(READ "${image}" header LIMIT 13)
  file(SIZE "${image}" size)
  if(NOT header STREQUAL "P6\n64 48\n255\n" OR NOT size EQUAL 9229)
    message(FATAL_ERROR "${image}: expected a 64x48 P6 image, "
            "found ${size} bytes starting \"${header}\"")
  endif()

else()
  message(FATAL_ERROR "unknown STEP \"${STEP}\"")
endif()
