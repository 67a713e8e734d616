# steps.cmake - the steps of the consumer tests (tests/consumer.cmake), run
# as `cmake -DSTEP=<step> -D... -P steps.cmake`:
#
#   install     cmake --install the build tree into WORK_DIR/prefix (fresh)
#   build       configure and build this directory (consumer.c, example.c)
#               against that prefix with find_package(raytrace)
#   run         run WORK_DIR/build/consumer
#   pkg-config  compile consumer.c with
#               `cc $(pkg-config --cflags --libs --static raytrace)`, run it
#   readme      check that the ```c block after the line
#               "<!-- example: tests/consumer/example.c -->" in README.md is
#               byte-identical to example.c
#   example     run WORK_DIR/build/example on scenes/one-facet.scn, check the
#               P6 it writes
#
# Inputs: SOURCE_DIR, BINARY_DIR (of libraytrace), LIBDIR (its
# CMAKE_INSTALL_LIBDIR), WORK_DIR, CONFIG, GENERATOR, C_COMPILER, PKG_CONFIG.
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
  set(ENV{PKG_CONFIG_PATH} "${prefix}/${LIBDIR}/pkgconfig")
  execute_process(COMMAND "${PKG_CONFIG}" --modversion raytrace
                  OUTPUT_VARIABLE version OUTPUT_STRIP_TRAILING_WHITESPACE
                  RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "pkg-config does not find raytrace.pc in ${prefix}")
  endif()
  execute_process(COMMAND "${PKG_CONFIG}" --cflags --libs --static raytrace
                  OUTPUT_VARIABLE flags OUTPUT_STRIP_TRAILING_WHITESPACE
                  COMMAND_ERROR_IS_FATAL ANY)
  message("raytrace.pc ${version}: ${flags}")
  separate_arguments(flags UNIX_COMMAND "${flags}")
  set(program "${WORK_DIR}/pkg-config-consumer")
  file(REMOVE "${program}")
  run("compiling with pkg-config's flags" "${C_COMPILER}" -std=c11 -Wall
      -Wextra -Wpedantic -Werror "${CMAKE_CURRENT_LIST_DIR}/consumer.c"
      -o "${program}" ${flags})
  run("the pkg-config consumer" "${program}")

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
