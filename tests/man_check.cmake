# man_check.cmake - the checks of tests/man.cmake, run as
# `cmake -DSTEP=<step> -DPAGE=<page.1> [-DPROGRAM=<program>] -P man_check.cmake`:
#
#   options  every long option in PROGRAM --help's option lines
#            ("  -o, --output=OUT ...", "      --depth=N ...") appears in
#            PAGE's source as \-\-name; fewer than MIN_OPTIONS lines
#            (default 10) means the help was not read as expected
#   render   groff -man -Tutf8 -ww renders PAGE with nothing on stderr
#            (prints "MAN-SKIP: ..." without groff)
#   answers  PROGRAM --help exits 0 with a usage line naming NAME on
#            standard output; PROGRAM --version exits 0 printing exactly
#            "NAME (libraytrace) VERSION"; both with nothing on stderr
cmake_minimum_required(VERSION 3.20)

if(STEP STREQUAL "options")
  execute_process(COMMAND "${PROGRAM}" --help OUTPUT_VARIABLE help
                  RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${PROGRAM} --help failed (${result})")
  endif()
  file(READ "${PAGE}" page)
  string(REPLACE "\\-" "-" page "${page}")
  string(REGEX MATCHALL "\n  [ ]*(-[A-Za-z], )?--[a-z][a-z-]*" lines "${help}")
  set(missing)
  set(count 0)
  foreach(line IN LISTS lines)
    string(REGEX MATCH "--[a-z][a-z-]*" option "${line}")
    math(EXPR count "${count} + 1")
    string(REGEX MATCH "${option}([^a-z-]|$)" found "${page}")
    if(NOT found)
      list(APPEND missing "${option}")
    endif()
  endforeach()
  if(NOT MIN_OPTIONS)
    set(MIN_OPTIONS 10)
  endif()
  if(count LESS MIN_OPTIONS)
    message(FATAL_ERROR "found only ${count} options in ${PROGRAM} --help")
  endif()
  if(missing)
    string(REPLACE ";" " " missing "${missing}")
    message(FATAL_ERROR "${PAGE} does not describe: ${missing}")
  endif()
  message("${PAGE} names all ${count} long options of --help")

elseif(STEP STREQUAL "render")
  find_program(GROFF groff)
  if(NOT GROFF)
    message("MAN-SKIP: groff is not installed (Debian: apt-get install groff-base)")
    return()
  endif()
  execute_process(COMMAND "${GROFF}" -man -Tutf8 -ww -z "${PAGE}"
                  RESULT_VARIABLE result ERROR_VARIABLE warnings)
  if(NOT result EQUAL 0 OR NOT warnings STREQUAL "")
    message(FATAL_ERROR "groff on ${PAGE} (${result}):\n${warnings}")
  endif()
  message("${PAGE} renders without warnings")

elseif(STEP STREQUAL "answers")
  execute_process(COMMAND "${PROGRAM}" --help OUTPUT_VARIABLE help
                  ERROR_VARIABLE help_errors RESULT_VARIABLE result)
  string(TOLOWER "${help}" lower_help)
  if(NOT result EQUAL 0 OR NOT help_errors STREQUAL "" OR
     NOT lower_help MATCHES "^usage: ${NAME} ")
    message(FATAL_ERROR "${NAME} --help (${result}): stdout:\n${help}\n"
                        "stderr:\n${help_errors}")
  endif()
  execute_process(COMMAND "${PROGRAM}" --version OUTPUT_VARIABLE version
                  ERROR_VARIABLE version_errors RESULT_VARIABLE result)
  if(NOT result EQUAL 0 OR NOT version_errors STREQUAL "" OR
     NOT version STREQUAL "${NAME} (libraytrace) ${VERSION}\n")
    message(FATAL_ERROR "${NAME} --version (${result}): '${version}', "
                        "expected '${NAME} (libraytrace) ${VERSION}'\n"
                        "${version_errors}")
  endif()
  message("${NAME} answers --help and --version ${VERSION}")

else()
  message(FATAL_ERROR "unknown STEP \"${STEP}\"")
endif()
