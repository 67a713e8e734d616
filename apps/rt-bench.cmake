# rt-bench, the error-against-run-time report of docs/accuracy.md: a
# program to run by hand, not a test.  Its metrics, plot and CSV code is a
# static library, raytrace_bench, so that tests/bench.cmake can test it.
add_library(raytrace_bench STATIC
  bench/metrics.c
  bench/output_file.c
  bench/plot.c
  bench/report.c)
target_include_directories(raytrace_bench PUBLIC
  "${CMAKE_CURRENT_SOURCE_DIR}/bench")
target_link_libraries(raytrace_bench PUBLIC raytrace::raytrace)
raytrace_set_warnings(raytrace_bench)

raytrace_add_program(rt-bench rt-bench.c LIBS raytrace_bench raytrace_cli)
