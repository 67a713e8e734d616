# raytrace_set_warnings(<target>): the project's warning flags, the
# floating-point rules of the library and the POSIX level its sources are
# written against (_POSIX_C_SOURCE, set here once for every target of the
# project), applied PRIVATE so that consumers - of the installed package or
# of the project through add_subdirectory - never inherit them.
#
# -ffp-contract=off: the watertight intersection test relies on a*b - c*d
# being rounded the same way for both triangles that share an edge; letting
# the compiler fuse it into an FMA breaks that (docs/robustness.md).
function(raytrace_set_warnings target)
  if(CMAKE_C_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE
      -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes
      -Wmissing-prototypes -Wno-missing-field-initializers
      -ffp-contract=off)
  elseif(MSVC)
    target_compile_options(${target} PRIVATE /W4 /fp:precise)
  endif()
  target_compile_definitions(${target} PRIVATE _POSIX_C_SOURCE=200809L)
  set_target_properties(${target} PROPERTIES C_STANDARD 11
                        C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
endfunction()
