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
#
# A step that cannot run here (no make, no SDL2 in the install, no
# sdl2-config) prints "KIT-SKIP: <why>", which kit.cmake turns into a
# skipped test.
# Inputs: SOURCE_DIR, PREFIX, LIBDIR (the install's CMAKE_INSTALL_LIBDIR),
# WORK_DIR, C_COMPILER, KIT_PPM (tests/kit_ppm.c's program).
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

else()
  message(FATAL_ERROR "unknown STEP \"${STEP}\"")
endif()
