# Linear float output (tests/test_float_output.c): test_float_output renders
# shipped scenes with rt_render_options.linear and writes PFM; its `exr`
# entry, test_float_output_exr, reads the OpenEXR files back with OpenEXR's
# C API and exits 77, a visible skip, in a build without OpenEXR.
# test_float_output_python reads rt-export's PFM with Python's struct
# (tests/float_output_check.py) against its PPM.
set(_rt_float_libs)
set(_rt_float_have_exr 0)
if(RAYTRACE_HAVE_EXR AND TARGET PkgConfig::RT_OPENEXR)
  set(_rt_float_libs PkgConfig::RT_OPENEXR)
  set(_rt_float_have_exr 1)
endif()
raytrace_add_suite(test_float_output LIBS ${_rt_float_libs})
target_compile_definitions(raytrace_test_float_output PRIVATE
  RT_TEST_HAVE_OPENEXR=${_rt_float_have_exr})
set_tests_properties(test_float_output PROPERTIES TIMEOUT 600)
add_test(NAME test_float_output_exr COMMAND raytrace_test_float_output exr
         WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
set_tests_properties(test_float_output_exr PROPERTIES
  SKIP_RETURN_CODE 77 TIMEOUT 600)
if(TARGET raytrace_rt_export)
  find_program(RT_PYTHON3 python3)
  if(RT_PYTHON3)
    add_test(NAME test_float_output_python
             COMMAND "${RT_PYTHON3}"
                     "${CMAKE_CURRENT_SOURCE_DIR}/float_output_check.py"
                     "$<TARGET_FILE:raytrace_rt_export>"
                     "${PROJECT_SOURCE_DIR}/scenes")
  else()
    add_test(NAME test_float_output_python
             COMMAND sh -c "echo 'SKIPPED: no python3'; exit 77")
  endif()
  set_tests_properties(test_float_output_python PROPERTIES
    SKIP_RETURN_CODE 77 TIMEOUT 600)
endif()
