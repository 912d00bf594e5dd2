# The fuzz build: -DMESHPARTICLES_FUZZ=ON with clang (scripts/fuzz.sh
# configures it in build-fuzz/). It builds one libFuzzer target per mesh
# format, and a structured one for VTK and VTP, from the readers, the mesh
# checks and fast marching, with ASan, UBSan and libstdc++ assertions, and
# nothing that needs OpenCL or OpenMesh.
option(MESHPARTICLES_FUZZ "Build the libFuzzer targets of the mesh readers (clang only) instead of the program" OFF)
if(MESHPARTICLES_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "MESHPARTICLES_FUZZ needs clang (e.g. CXX=clang++-14), not ${CMAKE_CXX_COMPILER_ID}")
  endif()
  set(SANITIZERS -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  # libstdc++'s own bounds checks (vector and span indexing) catch what ASan
  # cannot see inside an allocation.
  add_compile_definitions(_GLIBCXX_ASSERTIONS)
  add_library(fuzzed_mesh_input STATIC ${MESH_INPUT_SOURCES} ${GEODESIC_SOLVER_SOURCES})
  # Eight files to a unit, as in the program's build (CMakeLists.txt).
  set_target_properties(fuzzed_mesh_input PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
  target_include_directories(fuzzed_mesh_input PUBLIC host)
  find_package(EXPAT REQUIRED)  # the .vtp reader's XML and zlib, as in the program
  find_package(ZLIB REQUIRED)
  find_package(Threads REQUIRED)  # the solvers' set-up runs on the worker pool
  target_link_libraries(fuzzed_mesh_input PUBLIC EXPAT::EXPAT ZLIB::ZLIB Threads::Threads)
  target_compile_options(fuzzed_mesh_input PUBLIC -g -O1 ${SANITIZERS} -fsanitize=fuzzer-no-link)
  target_link_options(fuzzed_mesh_input PUBLIC ${SANITIZERS})
  # The finding rules every target shares.
  add_library(fuzz_checks STATIC fuzz/fuzz_checks.cpp)
  target_link_libraries(fuzz_checks PUBLIC fuzzed_mesh_input)
  foreach(format off ply obj stl vtk vtp)
    add_executable(fuzz_${format} fuzz/mesh_reader_fuzzer.cpp)
    target_compile_definitions(fuzz_${format} PRIVATE FUZZ_EXTENSION=".${format}")
    target_compile_options(fuzz_${format} PRIVATE -fsanitize=fuzzer)
    target_link_options(fuzz_${format} PRIVATE -fsanitize=fuzzer)
    target_link_libraries(fuzz_${format} PRIVATE fuzz_checks)
  endforeach()
  # Structured: VTK and VTP files written from a recipe the input describes
  # (fuzz/vtk_recipe.hpp), so mutations reach counts, offsets, pieces and
  # appended ranges in every encoding.
  add_executable(fuzz_vtk_structured fuzz/vtk_structured_fuzzer.cpp fuzz/vtk_recipe.cpp fuzz/recipe_file.cpp
                                     fuzz/legacy_vtk_writer.cpp fuzz/vtp_writer.cpp)
  target_compile_options(fuzz_vtk_structured PRIVATE -fsanitize=fuzzer)
  target_link_options(fuzz_vtk_structured PRIVATE -fsanitize=fuzzer)
  target_link_libraries(fuzz_vtk_structured PRIVATE fuzz_checks)
endif()
