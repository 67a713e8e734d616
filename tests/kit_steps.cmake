# kit_steps.cmake - the steps of the course-kit tests (tests/kit.cmake): a
# course-layout student project (tests/student/) built with its own
# course-style Makefile against the libraytrace installed in a prefix, as
# a student would after `cmake --install`.  Run as
# `cmake -DSTEP=<step> -D... -P kit_steps.cmake`:
#
#   all        copy tests/student (and scenes/cubes.scn) into WORK_DIR,
#              `make all`
#   tests      `make tests`: the graded test must print a full score
#   run        `make run`: cubes.p3 against rt-export --fast-sqrt's image
#   tests_sdl  `make tests_sdl` on SDL's dummy driver with IMGSDL_OUTPUT:
#              the example's gradient
#   run_sdl    `make run_sdl` likewise: the same pixels as `make run`'s
#   lm         a createFacet that calls sqrt: the course's test_note rule
#              fails to link, docs/in104.md's Makefile lines make
#              `make tests` link and print the full score
#   packages   the kit's other ways in: a program built with pkg-config's
#              raytrace-util (and raytrace-imgsdl) flags, and one with
#              find_package(raytrace COMPONENTS imgsdl), run
#
# A step that cannot run here (no make, no SDL2 in the install, no
# sdl2-config) prints "KIT-SKIP: <why>", which kit.cmake turns into a
# skipped test.
# Inputs: SOURCE_DIR, PREFIX, LIBDIR (the install's CMAKE_INSTALL_LIBDIR),
# WORK_DIR, C_COMPILER, KIT_PPM (tests/kit_ppm.c's program), PKG_CONFIG,
# GENERATOR.
cmake_minimum_required(VERSION 3.20)

set(student "${WORK_DIR}/student")
set(libdir "${PREFIX}/${LIBDIR}")

function(skip why)
  message("KIT-SKIP: ${why}")
endfunction()

# Runs `make TARGET` in the student project with the kit's variables; its
# output in the variable named by OUT.  Fails the test on failure.
function(student_make target out)
  set(command "${MAKE_PROGRAM}" ${target} "RAYTRACE=${PREFIX}"
      "RAYTRACE_LIB=${libdir}" "GCC=${C_COMPILER}")
  string(REPLACE ";" " " shown "${command}")
  message("$ ${shown}")
  execute_process(COMMAND ${command} WORKING_DIRECTORY "${student}"
                  RESULT_VARIABLE result OUTPUT_VARIABLE output
                  ERROR_VARIABLE output)
  message("${output}")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "make ${target} failed (${result})")
  endif()
  set(${out} "${output}" PARENT_SCOPE)
endfunction()

function(check_images what)
  execute_process(COMMAND "${KIT_PPM}" ${ARGN} RESULT_VARIABLE result
                  OUTPUT_VARIABLE output ERROR_VARIABLE output)
  message("${what}: ${output}")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${what}: the images differ more than allowed")
  endif()
endfunction()

find_program(MAKE_PROGRAM NAMES make gmake)
if(NOT MAKE_PROGRAM)
  skip("no make program")
  return()
endif()

if(STEP STREQUAL "all")
  file(REMOVE_RECURSE "${student}")
  file(COPY "${SOURCE_DIR}/tests/student/" DESTINATION "${student}")
  file(COPY "${SOURCE_DIR}/scenes/cubes.scn" DESTINATION "${student}/scenes")
  student_make(all output)

elseif(STEP STREQUAL "tests")
  student_make(tests output)
  if(NOT output MATCHES "Note finale \\(sur 2\\) : 2\\.00")
    message(FATAL_ERROR "the graded test did not print a full score, 2.00")
  endif()

elseif(STEP STREQUAL "run")
  file(REMOVE "${student}/cubes.p3")
  student_make(run output)
  if(NOT output MATCHES "\ncubes\\.p3\n" OR NOT EXISTS "${student}/cubes.p3")
    message(FATAL_ERROR "make run did not write cubes.p3 and print its path")
  endif()
  set(reference "${WORK_DIR}/rt-export-fast-sqrt.ppm")
  execute_process(COMMAND "${PREFIX}/bin/rt-export" "${student}/scenes/cubes.scn"
                  -o "${reference}" --fast-sqrt --quiet
                  RESULT_VARIABLE result COMMAND_ECHO STDOUT)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "the installed rt-export failed (${result})")
  endif()
  # docs/in104.md says why not byte for byte: fastInvSqrt's rounding moves
  # some channels by one level, and grazing rays on the edges of facets and
  # shadows go the other way under the handout's EPSILON.
  check_images("identical pixels (at most 5 % may differ)"
               compare "${reference}" "${student}/cubes.p3" 0 8000)
  check_images("within one level (at most 0.1 % beyond)"
               compare "${reference}" "${student}/cubes.p3" 1 160)

elseif(STEP STREQUAL "tests_sdl" OR STEP STREQUAL "run_sdl")
  if(NOT EXISTS "${libdir}/libraytrace-imgsdl.a")
    skip("libraytrace was built without SDL2: no libraytrace-imgsdl.a")
    return()
  endif()
  find_program(SDL2_CONFIG sdl2-config)
  if(NOT SDL2_CONFIG)
    skip("no sdl2-config (Debian: apt-get install libsdl2-dev)")
    return()
  endif()
  set(picture "${WORK_DIR}/${STEP}.ppm")
  file(REMOVE "${picture}")
  set(ENV{SDL_VIDEODRIVER} dummy)
  set(ENV{SDL_AUDIODRIVER} dummy)
  set(ENV{IMGSDL_OUTPUT} "${picture}")
  student_make(${STEP} output)
  if(STEP STREQUAL "tests_sdl")
    check_images("the example's gradient" gradient "${picture}" 64 48)
  else()
    check_images("the window's picture is make run's"
                 compare "${student}/cubes.p3" "${picture}")
  endif()

elseif(STEP STREQUAL "lm")
  # A student whose createFacet normalises with sqrt: the course's
  # test_note rule (no $(LIBS)) does not link; with docs/in104.md's lines
  # applied to the Makefile, `make tests` links and gives the full score.
  set(student "${WORK_DIR}/student-lm")
  file(REMOVE_RECURSE "${student}")
  file(COPY "${SOURCE_DIR}/tests/student/" DESTINATION "${student}")
  file(READ "${student}/src/geometry.c" before)
  string(REPLACE "fastInvSqrt((float)n2)" "1.0 / sqrt(n2)" code "${before}")
  string(REPLACE "#include \"util.h\"" "#include <math.h>\n#include \"util.h\""
         code "${code}")
  if(code STREQUAL before OR NOT code MATCHES "sqrt\\(n2\\)")
    message(FATAL_ERROR "tests/student/src/geometry.c changed: no fastInvSqrt((float)n2) to replace by sqrt")
  endif()
  file(WRITE "${student}/src/geometry.c" "${code}")

  # The course's rule, as tests/student/Makefile keeps it: no $(LIBS).
  file(READ "${student}/Makefile" makefile)
  if(NOT makefile MATCHES "\n\t\\$\\(GCC\\) -Iinclude -o bin/\\$\\(EXEC_NOTE\\) \\$\\(TESTS_NOTE\\)\n")
    message(FATAL_ERROR "tests/student/Makefile: the course's test_note rule is not there")
  endif()
  execute_process(COMMAND "${MAKE_PROGRAM}" tests "RAYTRACE=${PREFIX}"
                  "RAYTRACE_LIB=${libdir}" "GCC=${C_COMPILER}"
                  WORKING_DIRECTORY "${student}" RESULT_VARIABLE result
                  OUTPUT_VARIABLE output ERROR_VARIABLE output)
  message("without the documented rule, make tests: exit ${result}\n${output}")
  if(result EQUAL 0)
    message("note: it linked without -lm here (this C library has sqrt in libc); "
            "the documented lines are still checked below")
  elseif(NOT output MATCHES "sqrt")
    message(FATAL_ERROR "make tests failed, but not for want of sqrt")
  endif()

  # The documented lines: the first ```make block of the section "The
  # lines to change in the course's Makefile", applied as a student would:
  # each `NAME = value` replaces NAME's definition, a rule replaces the
  # rule of that target (its first recipe line).
  file(READ "${SOURCE_DIR}/docs/in104.md" doc)
  string(FIND "${doc}" "### The lines to change in the course's Makefile" at)
  if(at LESS 0)
    message(FATAL_ERROR "docs/in104.md: no section \"The lines to change in the course's Makefile\"")
  endif()
  string(SUBSTRING "${doc}" ${at} -1 doc)
  string(FIND "${doc}" "```make\n" start)
  math(EXPR start "${start} + 8")
  string(SUBSTRING "${doc}" ${start} -1 doc)
  string(FIND "${doc}" "\n```" end)
  string(SUBSTRING "${doc}" 0 ${end} block)
  string(REPLACE "\n" ";" lines "${block}")
  list(LENGTH lines count)
  set(i 0)
  set(rules 0)
  while(i LESS count)
    list(GET lines ${i} line)
    math(EXPR i "${i} + 1")
    if(line MATCHES "^([A-Za-z_]+)[ \t]*=")
      set(name "${CMAKE_MATCH_1}")
      if(NOT makefile MATCHES "\n${name}[ \t]*=")
        message(FATAL_ERROR "the Makefile defines no ${name}")
      endif()
      string(REGEX REPLACE "\n${name}[ \t]*=[^\n]*" "\n${line}" makefile "${makefile}")
    elseif(line MATCHES "^([^\t=]+):" AND i LESS count)
      list(GET lines ${i} recipe)
      math(EXPR i "${i} + 1")
      string(REGEX REPLACE "([][$().*+?^|\\\\])" "\\\\\\1" target "${CMAKE_MATCH_1}")
      if(NOT makefile MATCHES "\n${target}:[^\n]*\n\t[^\n]*")
        message(FATAL_ERROR "the Makefile has no rule ${CMAKE_MATCH_1}")
      endif()
      string(REGEX REPLACE "\n${target}:[^\n]*\n\t[^\n]*" "\n${line}\n${recipe}"
             makefile "${makefile}")
      math(EXPR rules "${rules} + 1")
    endif()
  endwhile()
  if(rules EQUAL 0)
    message(FATAL_ERROR "docs/in104.md's Makefile lines change no rule")
  endif()
  file(WRITE "${student}/Makefile" "${makefile}")
  student_make(clean output)
  student_make(tests output)
  if(NOT output MATCHES "Note finale \\(sur 2\\) : 2\\.00")
    message(FATAL_ERROR "the graded test did not print a full score, 2.00")
  endif()

elseif(STEP STREQUAL "packages")
  set(dir "${WORK_DIR}/packages")
  file(REMOVE_RECURSE "${dir}")
  file(WRITE "${dir}/words.c" [=[
#include <stdio.h>
#include <string.h>
#include "util.h"
int main(void)
{
    char line[] = " 3,-3,-1, 400,400\n";
    char *words[6];
    splitLine(line, words, 6);
    if (strcmp(words[0], "3") || strcmp(words[4], "400") || words[5]) {
        puts("splitLine: wrong words");
        return 1;
    }
    printf("fastInvSqrt(4) = %.5f\n", fastInvSqrt(4.0f));
    return 0;
}
]=])
  set(imgsdl OFF)
  if(EXISTS "${libdir}/libraytrace-imgsdl.a")
    set(imgsdl ON)
  endif()
  if(PKG_CONFIG)
    set(ENV{PKG_CONFIG_PATH} "${libdir}/pkgconfig")
    execute_process(COMMAND "${PKG_CONFIG}" --cflags --libs raytrace-util
                    OUTPUT_VARIABLE flags OUTPUT_STRIP_TRAILING_WHITESPACE
                    COMMAND_ERROR_IS_FATAL ANY)
    message("raytrace-util.pc: ${flags}")
    separate_arguments(flags UNIX_COMMAND "${flags}")
    execute_process(COMMAND "${C_COMPILER}" -std=c11 -Wall -Wextra -Wpedantic
                    -Werror "${dir}/words.c" -o "${dir}/words" ${flags}
                    COMMAND_ERROR_IS_FATAL ANY)
    execute_process(COMMAND "${dir}/words" COMMAND_ERROR_IS_FATAL ANY)
    if(imgsdl)
      execute_process(COMMAND "${PKG_CONFIG}" --cflags --libs raytrace-imgsdl
                      OUTPUT_VARIABLE flags OUTPUT_STRIP_TRAILING_WHITESPACE
                      COMMAND_ERROR_IS_FATAL ANY)
      message("raytrace-imgsdl.pc: ${flags}")
      separate_arguments(flags UNIX_COMMAND "${flags}")
      execute_process(COMMAND "${C_COMPILER}" -std=c11 -Wall -Wextra -Werror
                      "${SOURCE_DIR}/tests/in104_imgsdl_student.c"
                      -o "${dir}/imgsdl-pc" ${flags} COMMAND_ERROR_IS_FATAL ANY)
    endif()
  endif()
  set(components)
  set(imgsdl_target)
  if(imgsdl)
    set(components COMPONENTS imgsdl)
    set(imgsdl_target "add_executable(imgsdl-cmake \"${SOURCE_DIR}/tests/in104_imgsdl_student.c\")\ntarget_link_libraries(imgsdl-cmake PRIVATE raytrace::imgsdl)")
  endif()
  file(WRITE "${dir}/CMakeLists.txt"
    "cmake_minimum_required(VERSION 3.20)\nproject(kit_packages C)\n"
    "find_package(raytrace REQUIRED ${components})\n"
    "add_executable(words words.c)\n"
    "target_link_libraries(words PRIVATE raytrace::util)\n${imgsdl_target}\n")
  execute_process(COMMAND "${CMAKE_COMMAND}" -S "${dir}" -B "${dir}/build"
                  -G "${GENERATOR}" "-DCMAKE_C_COMPILER=${C_COMPILER}"
                  "-DCMAKE_PREFIX_PATH=${PREFIX}" COMMAND_ERROR_IS_FATAL ANY)
  execute_process(COMMAND "${CMAKE_COMMAND}" --build "${dir}/build"
                  COMMAND_ERROR_IS_FATAL ANY)
  find_program(words words PATHS "${dir}/build" PATH_SUFFIXES Debug Release
               NO_DEFAULT_PATH REQUIRED)
  execute_process(COMMAND "${words}" COMMAND_ERROR_IS_FATAL ANY)
  if(imgsdl)
    set(ENV{SDL_VIDEODRIVER} dummy)
    set(ENV{IMGSDL_OUTPUT} "${dir}/gradient.ppm")
    find_program(drawer imgsdl-cmake PATHS "${dir}/build"
                 PATH_SUFFIXES Debug Release NO_DEFAULT_PATH REQUIRED)
    execute_process(COMMAND "${drawer}" "${SOURCE_DIR}/scenes/one-facet.scn"
                    COMMAND_ERROR_IS_FATAL ANY)
    check_images("find_package's raytrace::imgsdl" gradient
                 "${dir}/gradient.ppm" 40 30)
  else()
    message("no libraytrace-imgsdl.a: only raytrace::util was tried")
  endif()

else()
  message(FATAL_ERROR "unknown STEP \"${STEP}\"")
endif()
