# Each broken input: `meshparticles info FILE` exits 2 with one line naming the
# file and the problem.
set(DATA ${CMAKE_CURRENT_SOURCE_DIR}/data)
function(expect_exit_of name code pattern)
  add_test(NAME cli.${name} COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.sh ${code} ${pattern} ${ARGN})
endfunction()
function(expect_exit name code pattern)
  expect_exit_of(${name} ${code} ${pattern} $<TARGET_FILE:meshparticles> ${ARGN})
endfunction()

expect_exit(missing_file 2 "missing\\.off: no such file" info ${DATA}/missing.off)
expect_exit(directory 2 "is a directory" info ${DATA})
expect_exit(unknown_extension 2 "unknown_format\\.xyz: unknown mesh format" info ${DATA}/unknown_format.xyz)
expect_exit(garbage 2 "garbage\\.off: not a readable off file" info ${DATA}/garbage.off)
expect_exit(empty 2 "empty\\.off: .*no (vertices|faces)" info ${DATA}/empty.off)
expect_exit(no_faces 2 "no_faces\\.off: the mesh has no faces" info ${DATA}/no_faces.off)
expect_exit(truncated 2 "truncated\\.off: header declares 4 vertices but 2 could be read" info ${DATA}/truncated.off)
expect_exit(face_count_mismatch 2 "face_count_mismatch\\.off: header declares 5 faces but 4 could be read" info ${DATA}/face_count_mismatch.off)
expect_exit(nan_off 2 "nan_coordinate\\.off: header declares 4 vertices but 2 could be read" info ${DATA}/nan_coordinate.off)
expect_exit(nan_ply 2 "nan_coordinate\\.ply: vertex 2 has a NaN or infinite coordinate" info ${DATA}/nan_coordinate.ply)
expect_exit(index_out_of_range 2 "index_out_of_range\\.off: face 2 refers to vertex 7, out of range" info ${DATA}/index_out_of_range.off)
expect_exit(index_out_of_range_obj 2 "index_out_of_range\\.obj: .*out of range" info ${DATA}/index_out_of_range.obj)
expect_exit(repeated_index 2 "repeated_index\\.off: face 2 uses vertex 2 more than once" info ${DATA}/repeated_index.off)
expect_exit(nonmanifold_edge 2 "nonmanifold_edge\\.off: non-manifold edge 0-1" info ${DATA}/nonmanifold_edge.off)
expect_exit(nonmanifold_vertex 2 "nonmanifold_vertex\\.off: non-manifold vertex 0" info ${DATA}/nonmanifold_vertex.off)
# Tolerated with a one-line warning, exit 0.
expect_exit(degenerate_warns 0 "1 degenerate \\(zero-area\\) triangle" info ${DATA}/degenerate_triangle.off)
expect_exit(unreferenced_warns 0 "2 unreferenced vertices dropped" info ${DATA}/unreferenced_vertices.off)
expect_exit(quads_warn 0 "6 polygons with more than 3 vertices triangulated" info ${DATA}/cube_quads.off)
# Arguments and devices.
expect_exit(no_subcommand 2 "error: " )
expect_exit(unknown_subcommand 2 "error: " frobnicate)
expect_exit(unknown_device 2 "no OpenCL device matches 'no-such-device'" devices --device no-such-device)
# No OpenCL runtime at all: the ICD loader finds no vendor, the message names the package.
expect_exit_of(no_opencl_runtime 3 "no OpenCL platform found: install an OpenCL runtime .*pocl-opencl-icd"
            env OCL_ICD_VENDORS=${CMAKE_CURRENT_BINARY_DIR}/no-such-vendors-dir $<TARGET_FILE:meshparticles> devices)
# Geodesics on the command line.
expect_exit(geodesics_bad_source 2 "--source 99 is not a vertex of the surface" geodesics ${PROJECT_SOURCE_DIR}/meshes/tetrahedron.off --source 99)
expect_exit(geodesics_unwritable_out 2 "cannot write" geodesics ${PROJECT_SOURCE_DIR}/meshes/tetrahedron.off --source 0 --out /nonexistent-dir/d.txt)
expect_exit(geodesics_unknown_solver 2 "--geodesic" geodesics ${PROJECT_SOURCE_DIR}/meshes/tetrahedron.off --geodesic heat)
expect_exit(geodesics_table 0 "geodesics \\(fmm, [0-9]+ threads?\\): 4 done" geodesics ${PROJECT_SOURCE_DIR}/meshes/tetrahedron.off --no-cache)
expect_exit(geodesics_dropped_vertex 2 "--source 0 is not a vertex of the surface" geodesics ${DATA}/unreferenced_vertices.off --source 0 -q)
