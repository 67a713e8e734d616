# The course's API: the Check suites of the in104 layer, the
# student-style program built with the course's warning flags, and the same
# program compiled with the plain command line a student would type.

raytrace_add_suite(test_in104_geometry LIBS raytrace::in104)
raytrace_add_suite(test_in104_scene LIBS raytrace::in104)
raytrace_add_shared_test(test_in104_scene)

# in104_student.c uses nothing but the handout's headers and standard C; its
# exit status is its number of failed checks.
add_executable(raytrace_in104_student in104_student.c)
set_target_properties(raytrace_in104_student PROPERTIES
  OUTPUT_NAME in104_student)
target_link_libraries(raytrace_in104_student PRIVATE raytrace::in104)
if(CMAKE_C_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(raytrace_in104_student PRIVATE -Wall -Wextra -Werror)
endif()
add_test(NAME in104_student_program_gets_the_spec_results
         COMMAND raytrace_in104_student "${PROJECT_SOURCE_DIR}/scenes/cubes.scn"
         WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")

# The plain command line of docs/in104.md, against the build tree:
#   cc -Wall -Wextra -Werror -I<src>/include/in104 in104_student.c
#      -L<libdirs> -lraytrace-in104 -lraytrace -lm -lpthread
# plus the build's own CMAKE_C_FLAGS (empty in a normal build; the
# sanitizer flags under .ci/sanitize, which an instrumented library needs).
if(UNIX AND CMAKE_C_COMPILER_ID MATCHES "GNU|Clang")
  separate_arguments(in104_flags UNIX_COMMAND "${CMAKE_C_FLAGS}")
  set(in104_script [=[
cc=$1 include=$2 source=$3 libdir1=$4 libdir2=$5 program=$6 workdir=$7
shift 7
set -x
"$cc" "$@" -Wall -Wextra -Werror -I"$include" "$source" -L"$libdir1" -L"$libdir2" -lraytrace-in104 -lraytrace -lm -lpthread -o "$program" || exit 1
cd "$workdir" && "$program"
]=])
  add_test(NAME in104_student_program_builds_with_the_plain_cc_command
    COMMAND sh -c "${in104_script}" sh
      "${CMAKE_C_COMPILER}"
      "${PROJECT_SOURCE_DIR}/include/in104"
      "${CMAKE_CURRENT_SOURCE_DIR}/in104_student.c"
      "$<TARGET_FILE_DIR:raytrace::in104>"
      "$<TARGET_FILE_DIR:raytrace::raytrace>"
      "${CMAKE_CURRENT_BINARY_DIR}/in104_student_plain"
      "${CMAKE_CURRENT_BINARY_DIR}"
      ${in104_flags})
  # A shared build needs the loader to find the libraries of the build tree.
  set_tests_properties(in104_student_program_builds_with_the_plain_cc_command
    PROPERTIES ENVIRONMENT
    "LD_LIBRARY_PATH=$<TARGET_FILE_DIR:raytrace::in104>:$<TARGET_FILE_DIR:raytrace::raytrace>")
endif()

# The example program of apps/in104-render/ renders a scene, and fails on a bad one.
if(TARGET raytrace_in104_render)
  add_test(NAME in104_render_example_renders_a_scene
           COMMAND raytrace_in104_render "${PROJECT_SOURCE_DIR}/scenes/one-facet.scn"
                   in104-render-one-facet.ppm
           WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
  add_test(NAME in104_render_example_fails_on_a_missing_scene
           COMMAND raytrace_in104_render no-such-scene.scn
           WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
  set_tests_properties(in104_render_example_fails_on_a_missing_scene
                       PROPERTIES WILL_FAIL TRUE)
endif()

# The course's libutil: splitLine and fastInvSqrt.
raytrace_add_suite(test_in104_util LIBS raytrace::util)

# kit_ppm: the image checks of the kit's tests (here and tests/kit.cmake).
add_executable(raytrace_kit_ppm kit_ppm.c)
set_target_properties(raytrace_kit_ppm PROPERTIES OUTPUT_NAME kit_ppm)
raytrace_set_warnings(raytrace_kit_ppm)

# The course's libimgsdl, when SDL2 is found: a tests_imgsdl-style
# program whose main() is the library's, on SDL's dummy video driver.
if(TARGET raytrace::imgsdl)
  add_executable(raytrace_in104_imgsdl_student in104_imgsdl_student.c)
  set_target_properties(raytrace_in104_imgsdl_student PROPERTIES
    OUTPUT_NAME in104_imgsdl_student)
  target_link_libraries(raytrace_in104_imgsdl_student PRIVATE raytrace::imgsdl)
  raytrace_set_warnings(raytrace_in104_imgsdl_student)
  set(imgsdl_env SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy)
  set(imgsdl_out "${CMAKE_CURRENT_BINARY_DIR}/imgsdl-gradient.ppm")
  add_test(NAME imgsdl_main_draws_the_scene_and_writes_IMGSDL_OUTPUT
           COMMAND raytrace_in104_imgsdl_student "${PROJECT_SOURCE_DIR}/scenes/one-facet.scn")
  set_tests_properties(imgsdl_main_draws_the_scene_and_writes_IMGSDL_OUTPUT
    PROPERTIES ENVIRONMENT "${imgsdl_env};IMGSDL_OUTPUT=${imgsdl_out}"
               FIXTURES_SETUP imgsdl_drawn)
  add_test(NAME imgsdl_output_is_the_picture_traceSDLScene_drew
           COMMAND raytrace_kit_ppm gradient "${imgsdl_out}" 40 30)
  set_tests_properties(imgsdl_output_is_the_picture_traceSDLScene_drew
    PROPERTIES FIXTURES_REQUIRED imgsdl_drawn)
  add_test(NAME imgsdl_main_without_a_scene_prints_its_usage
           COMMAND raytrace_in104_imgsdl_student)
  add_test(NAME imgsdl_main_stops_when_parse_fails
           COMMAND raytrace_in104_imgsdl_student no-such-scene.scn)
  set_tests_properties(imgsdl_main_without_a_scene_prints_its_usage
    PROPERTIES ENVIRONMENT "${imgsdl_env}"
               PASS_REGULAR_EXPRESSION "usage: [^\n]* SCENE\\.scn")
  set_tests_properties(imgsdl_main_stops_when_parse_fails
    PROPERTIES ENVIRONMENT "${imgsdl_env}"
               PASS_REGULAR_EXPRESSION "imgsdl: cannot read the scene no-such-scene\\.scn")
  # A pass by message ignores the exit status: let the sanitizers' and
  # valgrind's reports still fail these two (.ci/sanitize, .ci/memcheck).
  set_tests_properties(imgsdl_main_without_a_scene_prints_its_usage
                       imgsdl_main_stops_when_parse_fails
    PROPERTIES FAIL_REGULAR_EXPRESSION "Sanitizer|runtime error|ERROR SUMMARY: [1-9]")
endif()
