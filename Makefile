# Makefile - the handout's commands, as a thin layer over CMake.
#
#   make, make all   configure build/ (Release) and build everything
#   make run         build rt-export and render scenes/cubes.scn to cubes.ppm
#                    (build/apps/rt-export prints the path it wrote)
#   make test        install missing dependencies (.ci/install-deps), build
#   make tests       with the test suites, run ctest in build/ and print
#                    the reason of each skipped test (tests/readme_skips.py)
#   make gallery     build rt-export, render docs/images/gallery/*.png and
#                    write docs/gallery.md (tools/gallery.sh)
#   make clean       remove build/ and cubes.ppm
#
# One build directory, build/, for every target, so that the handout's
# `build/apps/rt-export scenes/cubes.scn -o cubes.ppm` works after any of them.
# `make run` and `make all` need only a C compiler, make and CMake: the test
# suites are on only when Check is installed (RAYTRACE_TESTS=AUTO, the
# default), so configuring never fails for want of Check, and `make run`
# builds only rt-export (its target is raytrace_rt_export).  `make test`
# installs Check first and always turns them on.
#
# Builds are parallel: on every core, or within make's own job slots under
# `make -jN` (hence the `+` on those recipes, which `make -n` runs too).
#
# Variables: BUILD_TYPE (Release), CMAKE_FLAGS (more -D options for the
# configure step), CTEST_FLAGS (more options for ctest, e.g. -j8 or -R scene).
BUILD_DIR   := build
BUILD_TYPE  := Release
CMAKE_FLAGS :=
CTEST_FLAGS :=

# CMake's generated makefiles are make run by make: no "Entering directory".
MAKEFLAGS += --no-print-directory

CONFIGURE = cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) \
            $(CMAKE_FLAGS)
# Options before " -- " only: a variable set on the command line may hold -j.
PARALLEL = $$(case " $${MAKEFLAGS%% -- *}" in *" -j"*) ;; \
              *) echo --parallel "$$(nproc 2>/dev/null || echo 4)" ;; esac)

.PHONY: all run test tests gallery clean

all:
	$(CONFIGURE) -DRAYTRACE_TESTS=AUTO
	+cmake --build $(BUILD_DIR) $(PARALLEL)

run:
	@$(CONFIGURE) -DRAYTRACE_TESTS=AUTO >/dev/null
	+@cmake --build $(BUILD_DIR) $(PARALLEL) --target raytrace_rt_export
	@$(BUILD_DIR)/apps/rt-export scenes/cubes.scn -o cubes.ppm

test:
	bash .ci/install-deps
	$(CONFIGURE) -DRAYTRACE_TESTS=ON
	+cmake --build $(BUILD_DIR) $(PARALLEL)
	cd $(BUILD_DIR) && { ctest --output-on-failure --output-junit ctest.xml \
	    $(CTEST_FLAGS); status=$$?; \
	  python3 ../tests/readme_skips.py ctest.xml 2>/dev/null; exit $$status; }

tests: test

gallery:
	@$(CONFIGURE) -DRAYTRACE_TESTS=AUTO >/dev/null
	+@cmake --build $(BUILD_DIR) $(PARALLEL) --target raytrace_rt_export
	RT_BUILD=$(BUILD_DIR) bash tools/gallery.sh

clean:
	rm -rf $(BUILD_DIR) cubes.ppm
