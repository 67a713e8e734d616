# rt-bench, the error-against-run-time report of docs/accuracy.md (issue 6):
# a program to run by hand, not a test.  Its metrics, plot and CSV code is a
# static library, raytrace_bench, so that tests/bench.cmake can test it.
add_library(raytrace_bench STATIC
  bench/metrics.c
  bench/output_file.c
  bench/plot.c
  bench/report.c)
target_include_directories(raytrace_bench PUBLIC
  "${CMAKE_CURRENT_SOURCE_DIR}/bench")
find_library(RAYTRACE_RTBENCH_LIBM m)
target_link_libraries(raytrace_bench PUBLIC raytrace::raytrace
  $<$<BOOL:${RAYTRACE_RTBENCH_LIBM}>:m>)
target_compile_definitions(raytrace_bench PRIVATE _POSIX_C_SOURCE=200809L)
raytrace_set_warnings(raytrace_bench)

add_executable(rt-bench rt-bench.c)
target_link_libraries(rt-bench PRIVATE raytrace_bench raytrace_cli)
target_compile_definitions(rt-bench PRIVATE _POSIX_C_SOURCE=200809L)
raytrace_set_warnings(rt-bench)
install(TARGETS rt-bench RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
