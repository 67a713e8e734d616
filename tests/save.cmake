# rt_image_save and rt_image_save_check (raytrace/image.h), one suite by
# family: what a path names (tests/test_save.c), signals during a save
# (test_save_signals.c), the formats (test_save_formats.c), and the cases
# that need root in a private mount namespace, a /dev of its own, read-only
# mounts, a file of another owner (test_save_privileged.c), which exits 77,
# a visible skip, where the process cannot unshare, mount, mknod and chown.
foreach(family "" _signals _formats _privileged)
  raytrace_add_suite(test_save${family})
  set_tests_properties(test_save${family} PROPERTIES TIMEOUT 600)
endforeach()
set_tests_properties(test_save_privileged PROPERTIES SKIP_RETURN_CODE 77)
# The PNG round trip decodes with libpng, when the library was built with it
# (PNG::PNG is made a global imported target in src/CMakeLists.txt).
if(RAYTRACE_HAVE_PNG AND TARGET PNG::PNG)
  target_link_libraries(raytrace_test_save_formats PRIVATE PNG::PNG)
  target_compile_definitions(raytrace_test_save_formats PRIVATE
    RT_TEST_HAVE_LIBPNG=1)
else()
  target_compile_definitions(raytrace_test_save_formats PRIVATE
    RT_TEST_HAVE_LIBPNG=0)
endif()

# Descriptors the caller opened (/dev/fd/N, /proc/self/fd/N, /dev/stdout,
# process substitution), tests/test_save_streams.c: test_save_streams calls
# the library; test_save_streams_shell runs rt-export in bash with the same
# destinations, and exits 77, a visible skip, without bash or rt-export.
raytrace_add_suite(test_save_streams)
set_tests_properties(test_save_streams PROPERTIES TIMEOUT 300)
add_test(NAME test_save_streams_shell
         COMMAND raytrace_test_save_streams shell
         WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
set_tests_properties(test_save_streams_shell PROPERTIES
  SKIP_RETURN_CODE 77
  TIMEOUT 300)
