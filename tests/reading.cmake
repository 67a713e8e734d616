# The reading layer's own suites (src/formats): the one lexer
# (tests/test_lexer.c), its numbers read as strtod reads them, by the fast
# path or not (tests/test_number_fast.c), the one framing of a view
# (tests/test_framing.c) and the builder's refusals as data, mapped by each reader to the token it
# kept (tests/test_refusals.c).  Included from tests/CMakeLists.txt.
foreach(suite test_lexer test_number_fast test_framing test_refusals)
  raytrace_add_suite(${suite} INTERNAL)
endforeach()
