# RAYTRACE_TESTS: AUTO builds the test suites when Check is found (through
# pkg-config: Debian's check installs only check.pc), ON requires Check,
# OFF skips them.  Sets RAYTRACE_TESTS_ENABLED, and PkgConfig::CHECK for
# tests/.  A plain configure without Check succeeds and says why the tests
# are off; asking for them without Check fails and says what to install.
string(TOUPPER "${RAYTRACE_TESTS}" _rt_tests_mode)
if(NOT _rt_tests_mode STREQUAL "AUTO")
  if(RAYTRACE_TESTS)
    set(_rt_tests_mode ON)
  else()
    set(_rt_tests_mode OFF)
  endif()
endif()

set(RAYTRACE_TESTS_ENABLED OFF)
if(NOT _rt_tests_mode STREQUAL "OFF")
  set(_rt_check_why "")
  find_package(PkgConfig QUIET)
  if(NOT PKG_CONFIG_FOUND)
    set(_rt_check_why "pkg-config not found")
  else()
    pkg_check_modules(CHECK QUIET IMPORTED_TARGET check)
    if(CHECK_FOUND)
      set(RAYTRACE_TESTS_ENABLED ON)
    else()
      set(_rt_check_why "pkg-config finds no check.pc")
    endif()
  endif()
  if(NOT RAYTRACE_TESTS_ENABLED)
    if(_rt_tests_mode STREQUAL "ON")
      message(FATAL_ERROR
        "RAYTRACE_TESTS=ON but the Check unit-test library was not found "
        "(${_rt_check_why}).  Install Check and pkg-config (Debian/Ubuntu: "
        "apt-get install check pkg-config; `make test` installs them), or "
        "configure with -DRAYTRACE_TESTS=OFF to build without the tests.")
    elseif(RAYTRACE_TOP_LEVEL)
      message(STATUS "tests disabled: Check not found (${_rt_check_why}); "
        "install check and pkg-config (Debian/Ubuntu: apt-get install check "
        "pkg-config) to build them, or -DRAYTRACE_TESTS=OFF to say so")
    endif()
  endif()
endif()
raytrace_feature_info(tests RAYTRACE_TESTS_ENABLED
  "the Check test suites (RAYTRACE_TESTS=${_rt_tests_mode})")
