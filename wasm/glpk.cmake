# GLPK for WebAssembly, compiled from the C sources that scripts/setup.sh fetched with
# `apt-get source glpk` into build/third_party. Built once per build folder.
file(GLOB glpk_roots ${CMAKE_SOURCE_DIR}/build/third_party/glpk-*/src/glpk.h)
if(NOT glpk_roots)
  message(FATAL_ERROR "GLPK sources not found under build/third_party: run scripts/setup.sh")
endif()
list(GET glpk_roots 0 glpk_header)
get_filename_component(glpk_src ${glpk_header} DIRECTORY)
file(GLOB_RECURSE glpk_sources ${glpk_src}/*.c)
list(FILTER glpk_sources EXCLUDE REGEX "/proxy/main\\.c$")
file(GLOB glpk_dirs LIST_DIRECTORIES true ${glpk_src}/*)
list(FILTER glpk_dirs EXCLUDE REGEX "\\.[ch]$")
add_library(glpk_wasm STATIC ${glpk_sources})
target_include_directories(glpk_wasm PRIVATE ${glpk_src} ${glpk_dirs})
target_include_directories(glpk_wasm SYSTEM PUBLIC ${glpk_src})
# -O2: with -O3, P1 over fertility's 41 slider positions took 1,534-1,661 ms against 1,480-1,570
# (three interleaved runs); -msimd128 gained nothing either.
target_compile_options(glpk_wasm PRIVATE -O2 -w)
