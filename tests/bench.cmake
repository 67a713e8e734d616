# rt-bench's metrics: built when tools/rt-bench/CMakeLists.txt made the
# raytrace_bench library.
if(TARGET raytrace_bench)
  raytrace_add_suite(test_metrics LIBS raytrace_bench)
endif()
# rt-embree-peer, the Embree 3 peer of the benchmarks: only where it is built
# (tools/CMakeLists.txt, Embree 3 found).  It casts the rays rt-export casts,
# counted by kind (tests/embree_peer_rays.sh); no timing is checked.
if(TARGET raytrace_rt_embree_peer)
  find_program(BASH_PROGRAM bash)
  if(BASH_PROGRAM)
    add_test(NAME embree_peer_casts_the_rays_rt_export_casts
      COMMAND "${BASH_PROGRAM}"
              "${CMAKE_CURRENT_SOURCE_DIR}/embree_peer_rays.sh")
    set_tests_properties(embree_peer_casts_the_rays_rt_export_casts PROPERTIES
      ENVIRONMENT "RT_EMBREE_PEER=$<TARGET_FILE:raytrace_rt_embree_peer>;RT_EXPORT=$<TARGET_FILE:raytrace_rt_export>;RT_SOURCE_DIR=${PROJECT_SOURCE_DIR}"
      SKIP_RETURN_CODE 77 TIMEOUT 120)
  endif()
endif()
