# Third-party libraries, all from Debian's packages (scripts/setup.sh installs them).
# Natively they are found where Debian puts them. For Emscripten, header-only libraries are reached
# through a build-local folder of symlinks (never /usr/include itself, whose system headers would
# shadow Emscripten's), and GLPK is compiled from its Debian source package.
add_library(tessera_deps INTERFACE)

set(TESSERA_HEADER_ONLY
  "/usr/include/eigen3/Eigen"
  "/usr/include/eigen3/unsupported"
  "/usr/include/tiny_gltf.h"
  "/usr/include/nlohmann"
  "/usr/include/stb"
  "/usr/include/lemon")

if(EMSCRIPTEN)
  set(link_dir ${CMAKE_BINARY_DIR}/include)
  file(MAKE_DIRECTORY ${link_dir})
  foreach(target IN LISTS TESSERA_HEADER_ONLY)
    if(NOT EXISTS ${target})
      message(FATAL_ERROR "${target} is missing: run scripts/setup.sh")
    endif()
    get_filename_component(name ${target} NAME)
    file(CREATE_LINK ${target} ${link_dir}/${name} SYMBOLIC)
  endforeach()
  target_include_directories(tessera_deps SYSTEM INTERFACE ${link_dir} ${link_dir}/stb)
  include(${CMAKE_SOURCE_DIR}/wasm/glpk.cmake)
  target_link_libraries(tessera_deps INTERFACE glpk_wasm)
else()
  find_package(Eigen3 3.3 REQUIRED NO_MODULE)
  find_path(TINYGLTF_INCLUDE tiny_gltf.h REQUIRED)
  find_path(NLOHMANN_INCLUDE nlohmann/json.hpp REQUIRED)
  find_path(STB_INCLUDE stb_image.h PATH_SUFFIXES stb REQUIRED)
  find_path(LEMON_INCLUDE lemon/matching.h REQUIRED)
  find_path(GLPK_INCLUDE glpk.h REQUIRED)
  find_library(GLPK_LIBRARY glpk REQUIRED)
  target_include_directories(tessera_deps SYSTEM INTERFACE
    ${TINYGLTF_INCLUDE} ${NLOHMANN_INCLUDE} ${STB_INCLUDE} ${LEMON_INCLUDE} ${GLPK_INCLUDE})
  target_link_libraries(tessera_deps INTERFACE Eigen3::Eigen ${GLPK_LIBRARY})
endif()
