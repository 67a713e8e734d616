# What a load may cost and what it says (docs/robustness-input.md, "Budgets
# of a load"): tests/test_load_budgets.c (the cut of NFF's spheres and
# cones, the facet budget, lights, Ks + T, cancellation) and
# tests/test_load_warnings.c (warnings stored as needed and summarised,
# repeated facets, names shown escaped).  Included from tests/CMakeLists.txt.
raytrace_add_suite(test_load_budgets INTERNAL)
raytrace_add_suite(test_load_warnings INTERNAL)
# What a scene holds and what a load costs in memory (tests/test_memory.c:
# the materials' table, compact records, page-mapped build arrays, the
# peak in --stats).
raytrace_add_suite(test_memory INTERNAL)
