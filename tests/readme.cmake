# readme_commands: every command line of README.md's ```sh blocks, run as
# written in a scratch folder (copies of scenes/, examples/, include/ and a
# link to the build), and the scenes/ and build/apps/ paths docs/*.md's
# shell blocks name (tests/readme_commands.py).  Lines that cannot run here
# are marked in the README with their reason, which the test prints.  Needs
# python3 and the programs: skipped (77, with its reason) without python3.
find_program(RT_README_PYTHON python3)
if(RT_README_PYTHON)
  add_test(NAME readme_commands
    COMMAND "${RT_README_PYTHON}"
            "${CMAKE_CURRENT_SOURCE_DIR}/readme_commands.py"
            "${PROJECT_SOURCE_DIR}" "${PROJECT_BINARY_DIR}")
else()
  add_test(NAME readme_commands COMMAND sh -c
    "echo 'SKIP: readme_commands needs python3'; exit 77")
endif()
# rt-view's lines each wait 5 s under Xvfb; the MPI line starts 4 ranks.
set_tests_properties(readme_commands PROPERTIES SKIP_RETURN_CODE 77
  TIMEOUT 600 RESOURCE_LOCK xvfb LABELS readme)
