# Each broken input: `meshparticles info FILE` exits 2 with one line naming the
# file and the problem.
set(DATA ${CMAKE_CURRENT_SOURCE_DIR}/data)
# Labelled `fast`, and `device` where the command may open an OpenCL device;
# the end-to-end scripts below are `slow`.
function(expect_exit_of name code pattern)
  add_test(NAME cli.${name} COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.sh ${code} ${pattern} ${ARGN})
  if(ARGN MATCHES "(^|;)(run|batch|sweep|bench|devices|--balls)(;|$)")
    set_tests_properties(cli.${name} PROPERTIES LABELS "fast;device")
  else()
    set_tests_properties(cli.${name} PROPERTIES LABELS fast)
  endif()
endfunction()
function(expect_exit name code pattern)
  expect_exit_of(${name} ${code} ${pattern} $<TARGET_FILE:meshparticles> ${ARGN})
endfunction()
# A run that must succeed is held to what it writes (tests/expect_run.sh):
# exit 0 and its stderr line as above, then OUT's output set whole (each
# file at the size and SHA-256 report.json records, particles.particles of
# params.n lines) and each CHECK of report.json ("params.n=64 distances.store=local").
function(expect_run_of name pattern out checks)
  add_test(NAME cli.${name} COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/expect_run.sh ${out} "${checks}" ${pattern} ${ARGN})
  set_tests_properties(cli.${name} PROPERTIES LABELS "fast;device")
endfunction()
function(expect_run name pattern out checks)
  expect_run_of(${name} ${pattern} ${out} "${checks}" $<TARGET_FILE:meshparticles> ${ARGN})
endfunction()

expect_exit(missing_file 2 "missing\\.off: no such file" info ${DATA}/missing.off)
expect_exit(directory 2 "is a directory" info ${DATA})
expect_exit(unknown_extension 2 "unknown_format\\.xyz: unknown mesh format" info ${DATA}/unknown_format.xyz)
expect_exit(garbage 2 "garbage\\.off: line 1: expected an OFF keyword" info ${DATA}/garbage.off)
expect_exit(empty 2 "empty\\.off: .*no (vertices|faces)" info ${DATA}/empty.off)
expect_exit(no_faces 2 "no_faces\\.off: the mesh has no faces" info ${DATA}/no_faces.off)
expect_exit(truncated 2 "truncated\\.off: header declares 4 vertices and 4 faces, more than the 12 bytes after it can hold" info ${DATA}/truncated.off)
expect_exit(face_count_mismatch 2 "face_count_mismatch\\.off: file ends after 4 of the 5 faces the header declares" info ${DATA}/face_count_mismatch.off)
expect_exit(nan_off 2 "nan_coordinate\\.off: vertex 2 has a NaN or infinite coordinate" info ${DATA}/nan_coordinate.off)
expect_exit(nan_ply 2 "nan_coordinate\\.ply: vertex 2 has a NaN or infinite coordinate" info ${DATA}/nan_coordinate.ply)
expect_exit(index_out_of_range 2 "index_out_of_range\\.off: face 2 refers to vertex 7, out of range" info ${DATA}/index_out_of_range.off)
expect_exit(index_out_of_range_obj 2 "index_out_of_range\\.obj: .*out of range" info ${DATA}/index_out_of_range.obj)
expect_exit(repeated_index 2 "repeated_index\\.off: face 2 uses vertex 2 more than once" info ${DATA}/repeated_index.off)
# A VTK file from a segmentation pipeline runs like any mesh; a volume grid is refused.
expect_run(run_vtk "spread: [0-9]+ done" ${CMAKE_CURRENT_BINARY_DIR}/cli_run_vtk "params.n=20 params.method=spread mesh.vertices=400" run ${DATA}/vtk/patch_vtk51_binary.vtk -n 20 --no-cache --out ${CMAKE_CURRENT_BINARY_DIR}/cli_run_vtk)
expect_exit(vtk_truncated 2 "patch_meshio_binary_truncated\\.vtk: line [0-9]+: POINTS: 1200 values, more than the" info ${DATA}/vtk/patch_meshio_binary_truncated.vtk)
# Found by fuzz_vtp: a base64 problem was reported without the file's name.
expect_exit(vtp_not_base64 2 "error: [^ ]*not_base64_connectivity\\.vtp: <Polys> connectivity: not base64 data$" info ${DATA}/vtk/not_base64_connectivity.vtp)
# Tolerated with a one-line warning, exit 0.
expect_exit(degenerate_warns 0 "1 degenerate \\(zero-area\\) triangle" info ${DATA}/degenerate_triangle.off)
expect_exit(unreferenced_warns 0 "2 unreferenced vertices dropped" info ${DATA}/unreferenced_vertices.off)
expect_exit(quads_warn 0 "6 polygons with more than 3 vertices triangulated" info ${DATA}/cube_quads.off)
# Arguments and devices.
expect_exit(unknown_subcommand 2 "error: unknown command 'frobnicate' \\(commands: info, " frobnicate)
expect_exit(bad_option_before_command 2 "error: .*--frobnicate" --frobnicate run)
add_test(NAME cli.command_guide COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/command_guide.sh $<TARGET_FILE:meshparticles>
                                        ${PROJECT_VERSION})
set_tests_properties(cli.command_guide PROPERTIES LABELS fast)
expect_exit(unknown_device 2 "--device='no-such-device' matches no device above" devices --device no-such-device)
# No OpenCL runtime at all: the ICD loader finds no vendor, the message names the package.
expect_exit_of(no_opencl_runtime 3 "no OpenCL platform found: install an OpenCL runtime .*pocl-opencl-icd"
            env OCL_ICD_VENDORS=${CMAKE_CURRENT_BINARY_DIR}/no-such-vendors-dir $<TARGET_FILE:meshparticles> devices)
# Geodesics on the command line.
expect_exit(geodesics_bad_source 2 "--source 99 is not a vertex of the surface" geodesics ${PROJECT_SOURCE_DIR}/meshes/tetrahedron.off --source 99)
expect_exit(geodesics_unwritable_out 2 "cannot write" geodesics ${PROJECT_SOURCE_DIR}/meshes/tetrahedron.off --source 0 --out /nonexistent-dir/d.txt)
expect_exit(geodesics_unknown_solver 2 "--geodesic" geodesics ${PROJECT_SOURCE_DIR}/meshes/tetrahedron.off --geodesic heat)
# Balls by the fast iterative method, on the device and on the host: what
# `geodesics --balls` prints (stdout), and what --balls needs.
foreach(where device host)
  set(flag "")
  if(where STREQUAL host)
    set(flag --host)
  endif()
  add_test(NAME cli.geodesics_balls_fim_${where}
           COMMAND bash -c "$<TARGET_FILE:meshparticles> geodesics ${PROJECT_SOURCE_DIR}/meshes/torus.off --balls 200 --ball-radius 0.5 --geodesic fim ${flag} -q | tee /dev/stderr | grep -Ezq 'count +200 balls of radius 0.5, [0-9]+ vertices on average.*against fmm 0.00[0-9]+% mean'")
  set_tests_properties(cli.geodesics_balls_fim_${where} PROPERTIES LABELS "fast;device")
endforeach()
expect_exit(geodesics_balls_need_radius 2 "--balls requires --ball-radius" geodesics ${PROJECT_SOURCE_DIR}/meshes/torus.off --balls 20)
expect_run(run_local_fim "converged" ${CMAKE_CURRENT_BINARY_DIR}/run_local_fim "params.n=100 params.method=paper params.geodesic=fim distances.store=local distances.balls_on_device>0" run ${PROJECT_SOURCE_DIR}/meshes/torus.off -n 100 --method paper --distances local --geodesic fim --no-cache --out ${CMAKE_CURRENT_BINARY_DIR}/run_local_fim)
# The table's line on stdout: the 4 x 4 table, not from the cache.
expect_exit_of(geodesics_table 0 "geodesics \\(fmm, [0-9]+ threads?\\): 4 done"
               bash -o pipefail -c "\"$0\" geodesics ${PROJECT_SOURCE_DIR}/meshes/tetrahedron.off --no-cache | grep -Ezq 'table +4 x 4 float32.*from cache no'" $<TARGET_FILE:meshparticles>)
expect_exit(geodesics_dropped_vertex 2 "--source 0 is not a vertex of the surface" geodesics ${DATA}/unreferenced_vertices.off --source 0 -q)
# meshparticles run: bad arguments exit 2 with one clear line.
set(TORUS ${PROJECT_SOURCE_DIR}/meshes/torus.off)
set(TETRA ${PROJECT_SOURCE_DIR}/meshes/tetrahedron.off)
set(RUN_OUT ${CMAKE_CURRENT_BINARY_DIR}/cli_run)
expect_exit(run_zero_particles 2 "-n/--particles: expected a whole number from 1 to 4294967295, got \"0\"" run ${TETRA} -n 0 --out ${RUN_OUT}_run_zero_particles)
expect_exit(run_too_many_particles 2 "-n 5 is more particles than the 4 vertices of .*tetrahedron\\.off" run ${TETRA} -n 5 --out ${RUN_OUT}_run_too_many_particles)
expect_exit(run_zero_sigma 2 "--sigma: expected a finite number above 0, got \"0\"" run ${TETRA} -n 2 --sigma 0 --out ${RUN_OUT}_run_zero_sigma)
expect_exit(run_negative_sigma 2 "--sigma: expected a finite number above 0, got \"-1\"" run ${TETRA} -n 2 --sigma -1 --out ${RUN_OUT}_run_negative_sigma)
expect_exit(run_unknown_backend 2 "--backend: cuda not in" run ${TETRA} --backend cuda --out ${RUN_OUT}_run_unknown_backend)
expect_exit(run_unknown_scheme 2 "--scheme: jacobi not in" run ${TETRA} --scheme jacobi --out ${RUN_OUT}_run_unknown_scheme)
expect_exit(run_zero_colors 2 "--colors: expected a whole number from 1 to 4096, got \"0\"" run ${TETRA} --colors 0 --out ${RUN_OUT}_run_zero_colors)
expect_exit(run_colors_without_colored 2 "--colors applies to --scheme colored and monotone, not synchronous" run ${TETRA} -n 2 --scheme synchronous --colors 4 --out ${RUN_OUT}_run_colors_without_colored)
expect_run(run_sequential_on_device "converged" ${RUN_OUT}_sequential_on_device "params.n=2 params.backend=tiled params.scheme=sequential" run ${TETRA} -n 2 --backend tiled --scheme sequential --no-cache --out ${RUN_OUT}_sequential_on_device)
expect_exit(run_refused_work_group 2 "--wg 1000000 exceeds the maximum work-group size [0-9]+" run ${TETRA} -n 2 --backend tiled --wg 1000000 --no-cache --out ${RUN_OUT}_run_refused_work_group)
expect_exit(run_refused_tile 2 "needs [0-9]+ bytes of local memory. .* has [0-9]+" run ${TETRA} -n 2 --backend tiled --tile 16000000 --no-cache --out ${RUN_OUT}_run_refused_tile)
expect_exit(run_tile_on_naive 2 "--tile applies to the tiled backend only" run ${TETRA} -n 2 --backend naive --tile 8 --no-cache --out ${RUN_OUT}_run_tile_on_naive)
expect_exit(run_wg_on_serial 2 "--wg and --tile apply to the device backends \\(naive, tiled or field\\), not serial" run ${TETRA} -n 2 --backend serial --wg 8 --no-cache --out ${RUN_OUT}_run_wg_on_serial)
expect_exit(run_tile_on_field 2 "--tile applies to the tiled backend only" run ${TETRA} -n 2 --backend field --tile 8 --no-cache --out ${RUN_OUT}_run_tile_on_field)
expect_exit(run_weights_on_tiled 2 "--weights and --rebuild-every apply to the serial-field and field backends, not tiled" run ${TETRA} -n 2 --backend tiled --weights half --no-cache --out ${RUN_OUT}_run_weights_on_tiled)
expect_exit(run_rebuild_on_serial 2 "--weights and --rebuild-every apply to the serial-field and field backends, not serial" run ${TETRA} -n 2 --backend serial --rebuild-every 5 --no-cache --out ${RUN_OUT}_run_rebuild_on_serial)
expect_exit(run_unknown_weights 2 "--weights: double not in" run ${TETRA} -n 2 --backend field --weights double --out ${RUN_OUT}_run_unknown_weights)
expect_run(run_field_half "converged" ${RUN_OUT}_field_half "params.n=2 params.backend=field params.weights=half params.rebuild_every=3" run ${TETRA} -n 2 --backend field --weights half --rebuild-every 3 --no-cache --out ${RUN_OUT}_field_half)
# spread (the default) runs on the host; the paper's options imply paper, and
# name themselves when spread is asked for by name.
expect_run(run_spread_default "spread: [0-9]+ done in .*(converged|cycle)" ${RUN_OUT}_spread "params.n=16 params.method=spread params.method_from=default params.evening_diagrams=host params.device_from~default: params.measurement_balls=host params.geodesic=fmm distances.balls_on_device=0" run ${TORUS} -n 16 --out ${RUN_OUT}_spread)
# --device puts spread's evening diagrams on that device, and on a GPU its measurement's balls (by fim); on a
# CPU device (PoCL, named) the balls stay on the host unless --geodesic fim asks (0:0: the first device here).
expect_run(run_spread_device "spread: [0-9]+ done in .*(converged|cycle)" ${RUN_OUT}_spread_device "params.n=16 params.method=spread params.evening_diagrams=device params.device_from=--device params.measurement_balls=host params.geodesic=fmm distances.balls_on_device=0" run ${TORUS} -n 16 --device "Portable Computing Language" --out ${RUN_OUT}_spread_device)
expect_run(run_spread_device_fim "spread: [0-9]+ done in .*(converged|cycle)" ${RUN_OUT}_spread_device_fim "params.evening_diagrams=device params.measurement_balls=device params.geodesic=fim distances.balls_on_device>0" run ${TORUS} -n 16 --device 0:0 --geodesic fim --out ${RUN_OUT}_spread_device_fim)
# ... but not where --geodesic fmm asks for the host's method, nor on the dense table (solved on the host).
expect_run(run_spread_device_fmm "spread: [0-9]+ done in .*(converged|cycle)" ${RUN_OUT}_spread_device_fmm "params.evening_diagrams=device params.measurement_balls=host params.geodesic=fmm distances.balls_on_device=0" run ${TORUS} -n 16 --device 0:0 --geodesic fmm --out ${RUN_OUT}_spread_device_fmm)
expect_run(run_spread_device_dense "spread: [0-9]+ done in .*(converged|cycle)" ${RUN_OUT}_spread_device_dense "params.evening_diagrams=device params.measurement_balls=host params.geodesic=fmm distances.store=dense" run ${TORUS} -n 16 --device 0:0 --distances dense --no-cache --out ${RUN_OUT}_spread_device_dense)
expect_exit(run_spread_refuses_backend 2 "--backend applies to --method paper" run ${TETRA} -n 2 --method spread --backend tiled --out ${RUN_OUT}_run_spread_refuses_backend)
expect_exit(run_spread_refuses_v0 2 "--init v0 applies to --method paper" run ${TETRA} -n 2 --method spread --init v0 --out ${RUN_OUT}_run_spread_refuses_v0)
expect_exit(run_vertices_per_particle_on_paper 2 "--vertices-per-particle applies to --method spread" run ${TETRA} -n 2 --method paper --vertices-per-particle 50 --out ${RUN_OUT}_run_vertices_per_particle_on_paper)
expect_exit(run_vertices_per_particle_zero 2 "--vertices-per-particle: expected a finite number above 0, got \"0\"" run ${TETRA} -n 2 --vertices-per-particle 0 --out ${RUN_OUT}_run_vertices_per_particle_zero)
expect_exit(run_unknown_method 2 "--method: gradient not in" run ${TETRA} --method gradient --out ${RUN_OUT}_run_unknown_method)
expect_exit(run_bad_start_vertex 2 "--start-vertex 9 is not a vertex of the surface" run ${TETRA} -n 2 --init v0 --start-vertex 9 --out ${RUN_OUT}_run_bad_start_vertex)
expect_exit(run_unwritable_out 2 "cannot create the parent of output directory /dev/null: Not a directory" run ${TETRA} -n 2 --out /dev/null/out)
# Whole runs on the tetrahedron: every backend, files written, summary printed.
foreach(backend serial serial-field naive tiled field)
  expect_run(run_${backend} "particles: [0-9]+ done in .*(converged|iteration limit reached)" ${RUN_OUT}_${backend} "params.n=2 params.method=paper params.backend=${backend}" run ${TETRA} -n 2 --backend ${backend} --no-cache --out ${RUN_OUT}_${backend})
endforeach()
# A kernel that does not build: exit 2, the build log follows the message.
# expect_kernel_build_failure(NAME BACKEND FILE TEXT REGEX): `run --backend
# BACKEND` with kernels/FILE replaced by TEXT.
function(expect_kernel_build_failure name backend file text pattern)
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/broken_kernels_${name})
  file(COPY ${PROJECT_SOURCE_DIR}/kernels/ DESTINATION ${dir})
  file(WRITE ${dir}/${file} "${text}")
  expect_exit_of(${name} 2 ${pattern} env MESHPARTICLES_KERNEL_DIR=${dir}
                 $<TARGET_FILE:meshparticles> run ${TETRA} -n 2 --backend ${backend} --no-cache --out ${RUN_OUT}_${name})
  set_tests_properties(cli.${name} PROPERTIES ENVIRONMENT MULTILINE=1)
endfunction()
expect_kernel_build_failure(run_kernel_build_failure naive naive_update.cl
  "__kernel void naive_update( this is not OpenCL C\n" "OpenCL kernels failed to build \\(naive_update\\.cl.*build log:")
expect_kernel_build_failure(run_field_kernel_build_failure field field.h
  "#error the field header is broken\n" "OpenCL kernels failed to build \\(field_weights\\.cl.*build log:")
# Performance commands: bad arguments, then the tuning loop end to end.
expect_exit(sweep_zero_iterations 2 "--iterations: expected a whole number from 1 to 100000, got \"0\"" sweep ${TORUS} -n 8 --iterations 0 --no-cache)
expect_exit(sweep_tile_without_tiled 2 "--tile applies to the tiled kernel" sweep ${TORUS} --kernel naive --tile 8)
expect_exit(sweep_weights_without_field 2 "--weights applies to the field kernel, which is not swept" sweep ${TORUS} --kernel naive --weights half)
expect_exit(sweep_unknown_kernel 2 "--kernel: .cuda. is not one of naive, tiled, field" sweep ${TORUS} --kernel naive,cuda)
expect_exit(sweep_too_many_particles 2 "-n 5 is more particles than the 4 vertices" sweep ${TETRA} -n 5)
expect_exit(sweep_unwritable_csv 2 "/nonexistent-dir/s.csv: cannot write" sweep ${TETRA} -n 2 --csv /nonexistent-dir/s.csv)
expect_exit(sweep_colors_without_colored 2 "--colors applies to --scheme colored, not synchronous" sweep ${TORUS} --scheme synchronous --colors 4)
expect_exit(bench_colors_without_colored 2 "--colors applies to --scheme colored and monotone, not synchronous" bench --scheme synchronous --colors 4)
expect_exit(bench_bad_case 2 "--case 'torus': expected MESH:N" bench --case torus)
expect_exit(bench_unknown_mesh 2 "no built-in mesh named 'cube'" bench --case cube:8 --meshes-dir ${PROJECT_SOURCE_DIR}/meshes)
expect_exit(bench_too_many_particles 2 "--case torus:100000 is more particles than its 1500 vertices" bench --case torus:100000 --meshes-dir ${PROJECT_SOURCE_DIR}/meshes)
expect_exit(bench_zero_iterations 2 "--iterations: expected a whole number from 1 to 100000, got \"0\"" bench --case torus:8 --iterations 0)
add_test(NAME cli.performance_commands
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/performance_commands.sh $<TARGET_FILE:meshparticles> ${TORUS}
                 ${CMAKE_CURRENT_BINARY_DIR}/performance_commands ${PROJECT_SOURCE_DIR}/scripts/plot_sweep.py)
set_tests_properties(cli.performance_commands PROPERTIES LABELS "slow;device")
# Quality of particle files.
set(PARTICLES_DATA ${DATA}/particles)
expect_exit(quality_missing_file 2 "missing\\.particles: no such file" quality ${TORUS} ${PARTICLES_DATA}/missing.particles)
expect_exit(quality_bad_line 2 "two_numbers\\.particles: line 2 is not three numbers" quality ${TORUS} ${PARTICLES_DATA}/two_numbers.particles)
expect_exit(quality_nan 2 "nan\\.particles: line 2" quality ${TORUS} ${PARTICLES_DATA}/nan.particles)
expect_exit(quality_empty 2 "empty\\.particles: no particles" quality ${TORUS} ${PARTICLES_DATA}/empty.particles)
expect_exit(compare_needs_two 2 "particles" compare ${TORUS} ${PARTICLES_DATA}/blank_lines.particles)
expect_exit(compare_bad_second 2 "header\\.particles: line 1 is not three numbers" compare ${TORUS} ${PARTICLES_DATA}/blank_lines.particles ${PARTICLES_DATA}/header.particles)
add_test(NAME cli.quality_commands
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/quality_commands.sh $<TARGET_FILE:meshparticles> ${PROJECT_SOURCE_DIR}/meshes/patch.off
                 ${CMAKE_CURRENT_BINARY_DIR}/quality_commands ${PROJECT_SOURCE_DIR}/scripts)
set_tests_properties(cli.quality_commands PROPERTIES LABELS "slow;device")
expect_exit(bench_quality_csv 2 "--csv applies to the timing tables \\(with --quality, use --json\\)" bench --quality --csv ${CMAKE_CURRENT_BINARY_DIR}/q.csv)
# generate, info --json, devices and a failed sweep, checked in full.
# The paper's method reproduces the old default's moves bit for bit.
add_test(NAME cli.paper_method
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/paper_method.sh $<TARGET_FILE:meshparticles> ${PROJECT_SOURCE_DIR}/meshes
                 ${DATA} ${CMAKE_CURRENT_BINARY_DIR}/paper_method)
set_tests_properties(cli.paper_method PROPERTIES LABELS "fast;device")
add_test(NAME cli.command_outputs
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/command_outputs.sh $<TARGET_FILE:meshparticles> ${PROJECT_SOURCE_DIR}/meshes
                 ${PROJECT_SOURCE_DIR}/kernels ${CMAKE_CURRENT_BINARY_DIR}/command_outputs)
set_tests_properties(cli.command_outputs PROPERTIES LABELS "fast;device")
# run's summary, printed from the result, says what report.json says, for each method.
add_test(NAME cli.run_summary
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/run_summary.sh $<TARGET_FILE:meshparticles> ${PROJECT_SOURCE_DIR}/meshes
                 ${CMAKE_CURRENT_BINARY_DIR}/run_summary)
set_tests_properties(cli.run_summary PROPERTIES LABELS "fast;device")
# host/ depends one way: no folder includes a folder above it.
add_test(NAME layers COMMAND ${PROJECT_SOURCE_DIR}/scripts/check_layers.py)
set_tests_properties(layers PROPERTIES LABELS fast)
# Build logs name the real file and line.
# kernel_source() pastes headers into one string with #line markers; PoCL's
# compiler must report each error at its own file and line: in a pasted
# header, in the includer after its headers, and in the second file of a
# program (naive_update.cl, apply_moves.cl, particle_energies.cl).
expect_kernel_build_failure(kernel_error_names_header field field.h
  "// line 1\n// line 2\nthis is not OpenCL C;\n" "field\\.h:3:[0-9]+: ")
expect_kernel_build_failure(kernel_error_names_includer naive naive_update.cl
  "#include \"claims.h\"\n#include \"particle_energy.h\"\nthis is not OpenCL C;\n" "naive_update\\.cl:3:[0-9]+: ")
expect_kernel_build_failure(kernel_error_names_second_file naive apply_moves.cl
  "// line 1\nthis is not OpenCL C;\n" "apply_moves\\.cl:2:[0-9]+: ")

# Mesh input: the readers' dialects, hostile files, non-manifold input.
# Non-manifold input loads, with one warning line per kind (the strict
# refusals are tested in mesh_checks_test).
expect_exit(nonmanifold_edge_kept 0 "nonmanifold_edge\\.off: 1 non-manifold edge \\(e\\.g\\. 0-1, in 3 triangles\\) kept" info ${DATA}/nonmanifold_edge.off)
expect_exit(nonmanifold_vertex_kept 0 "nonmanifold_vertex\\.off: 1 non-manifold vertex \\(e\\.g\\. vertex 0, where 2 fans of triangles meet\\) kept" info ${DATA}/nonmanifold_vertex.off)
expect_exit(off_dialect 0 "off_dialect\\.off: 5 polygons with more than 3 vertices triangulated" info ${DATA}/off_dialect.off)
expect_exit(off_trailing_content 0 "trailing_content\\.off: 1 line after the 3 faces the header declares \\(from line 10\\) ignored" info ${DATA}/trailing_content.off)
expect_exit(obj_dialect 0 "obj_dialect\\.obj: 5 polygons" info ${DATA}/obj_dialect.obj)
expect_run(run_nonmanifold_vertex "particles: [0-9]+ done" ${RUN_OUT}_nonmanifold "params.n=3 params.backend=serial mesh.vertices=7" run ${DATA}/nonmanifold_vertex.off -n 3 --backend serial --no-cache --out ${RUN_OUT}_nonmanifold)
# What fuzzing the old readers found, each now one line and exit 2.
expect_exit(ply_header_cut 2 "header_cut_inside_element_line\\.ply: line 7: expected 'element NAME COUNT'" info ${DATA}/header_cut_inside_element_line.ply)
expect_exit(ply_count_2_31 2 "vertex_count_2147483647\\.ply: header declares 2147483647 'vertex' elements, more than the 6 bytes after it can hold" info ${DATA}/vertex_count_2147483647.ply)
expect_exit(ply_count_2_64 2 "vertex_count_2_64_minus_1\\.ply: line 3: the count of element 'vertex', '18446744073709551615', is not a count" info ${DATA}/vertex_count_2_64_minus_1.ply)
expect_exit(off_more_vertices 2 "more_vertices_than_declared\\.off: line 6: face 0 declares 0 vertices, fewer than a face needs" info ${DATA}/more_vertices_than_declared.off)
expect_exit(off_negative_face_size 2 "negative_face_size\\.off: line 6: face 0: expected its number of vertices, found '-3'" info ${DATA}/negative_face_size.off)
expect_exit(off_repeated_keyword 2 "repeated_keyword\\.off: line 2: expected 'Nvertices Nfaces \\[Nedges\\]', found 'OFF'" info ${DATA}/repeated_keyword.off)
expect_exit(off_binary 2 "binary\\.off: binary OFF is not supported" info ${DATA}/binary.off)
expect_exit(obj_relative_index 2 "relative_index_before_first\\.obj: line 4: relative index -4 reaches before the first vertex" info ${DATA}/relative_index_before_first.obj)
expect_exit(stl_binary_truncated 2 "binary_stl_truncated\\.stl: binary STL header declares 4 triangles \\(284 bytes\\) but the file has 234 bytes" info ${DATA}/binary_stl_truncated.stl)
# A mesh name on a device or a FIFO is refused at once, not read.
file(CREATE_LINK /dev/urandom ${CMAKE_CURRENT_BINARY_DIR}/urandom.stl SYMBOLIC)
expect_exit(device_refused 2 "urandom\\.stl: not a regular file" info ${CMAKE_CURRENT_BINARY_DIR}/urandom.stl)
set(FIFO ${CMAKE_CURRENT_BINARY_DIR}/fifo.off)
if(NOT EXISTS ${FIFO})
  execute_process(COMMAND mkfifo ${FIFO})
endif()
expect_exit(fifo_refused 2 "fifo\\.off: not a regular file" info ${FIFO})
set_tests_properties(cli.device_refused cli.fifo_refused PROPERTIES TIMEOUT 10)
# No area (issue 29): refused by every command that reads a mesh, not as "--sigma 0 is too small".
set(NO_AREA_MESSAGE "the mesh has no area: every triangle is degenerate \\(its corners at one point or on one line\\)")
expect_exit(no_area_run 2 "no_area\\.off: ${NO_AREA_MESSAGE}" run ${DATA}/no_area.off --out ${RUN_OUT}_no_area_run)
expect_exit(no_area_collinear_run 2 "no_area_collinear\\.off: ${NO_AREA_MESSAGE}" run ${DATA}/no_area_collinear.off -n 2 --out ${RUN_OUT}_no_area_collinear_run)
expect_exit(no_area_info 2 "no_area\\.off: ${NO_AREA_MESSAGE}" info ${DATA}/no_area.off)
expect_exit(no_area_geodesics 2 "no_area_collinear\\.off: ${NO_AREA_MESSAGE}" geodesics ${DATA}/no_area_collinear.off --no-cache)
expect_exit(no_area_quality 2 "no_area\\.off: ${NO_AREA_MESSAGE}" quality ${DATA}/no_area.off ${DATA}/particles/blank_lines.particles)
expect_exit(no_area_batch 2 "\\[1/1\\] no_area: refused: .*no_area\\.off: ${NO_AREA_MESSAGE}" batch ${DATA}/no_area.off --force --out ${CMAKE_CURRENT_BINARY_DIR}/batch_no_area)
set_tests_properties(cli.no_area_batch PROPERTIES ENVIRONMENT MULTILINE=1)
# Found by scripts/fuzz.sh: an element name of unprintable bytes, which went into the message as it was.
expect_exit(ply_unprintable_name 2 "unprintable_element_name\\.ply: line 4: the count of element 've[?]+[.][.][.]', '[?]', is not a count" info ${DATA}/unprintable_element_name.ply)

# Numbers parsed strictly, with the option and its range named.
expect_exit(number_negative 2 "--iterations: expected a whole number from 0 to 1000000, got \"-1\"" run ${TETRA} --iterations -1 --out ${RUN_OUT}_number_negative)
expect_exit(number_timed_negative 2 "--iterations: expected a whole number from 1 to 100000, got \"-1\"" bench --iterations -1)
expect_exit(number_sweep_negative 2 "--iterations: expected a whole number from 1 to 100000, got \"-1\"" sweep ${TETRA} --iterations -1)
expect_exit(number_leading_zero_is_decimal 2 "-n 10 is more particles than the 4 vertices" run ${TETRA} -n 010 --out ${RUN_OUT}_number_leading_zero_is_decimal)
expect_exit(number_hex 2 "-n/--particles: expected a whole number from 1 to 4294967295, got \"0x3\"" run ${TETRA} -n 0x3 --out ${RUN_OUT}_number_hex)
expect_exit(number_huge 2 "-n/--particles: expected a whole number from 1 to 4294967295, got \"99999999999999999999\"" run ${TETRA} -n 99999999999999999999 --out ${RUN_OUT}_number_huge)
expect_exit(number_words 2 "-n/--particles: expected a whole number from 1 to 4294967295, got \"abc\"" run ${TETRA} -n abc --out ${RUN_OUT}_number_words)
expect_exit(number_colors_cap 2 "--colors: expected a whole number from 1 to 4096, got \"4294967295\"" run ${TETRA} --colors 4294967295 --out ${RUN_OUT}_number_colors_cap)
expect_exit(number_wg_fraction 2 "--wg: expected a whole number from 1 to 1048576, got \"32.5\"" sweep ${TETRA} --wg 16,32.5)
expect_exit(number_case 2 "--case torus:-1: expected a whole number from 1 to 4294967295, got \"-1\"" bench --case torus:-1)
expect_exit(number_source 2 "--source: expected a whole number from 0 to 4294967295, got \"-1\"" geodesics ${TETRA} --source -1)
expect_exit(number_threads 2 "--threads: expected a whole number from 0 to 1024, got \"1e3\"" geodesics ${TETRA} --threads 1e3)
expect_exit(sigma_nan 2 "--sigma: expected a finite number above 0, got \"nan\"" run ${TETRA} --sigma nan --out ${RUN_OUT}_sigma_nan)
expect_exit(sigma_inf 2 "--sigma: expected a finite number above 0, got \"inf\"" quality ${TORUS} ${PARTICLES_DATA}/blank_lines.particles --sigma inf)
expect_exit(sigma_overflows 2 "--sigma 1e-300 is too small to compute with" run ${TETRA} -n 2 --backend serial --sigma 1e-300 --no-cache --out ${RUN_OUT}_sigma_overflows)
expect_run(sigma_tiny_warns "warning: --sigma 1e-05 with d_hex .*particles will not feel each other" ${RUN_OUT}_sigma_tiny "params.sigma=1e-05 params.sigma_from=--sigma" run ${TETRA} -n 2 --backend serial --sigma 1e-5 --no-cache --out ${RUN_OUT}_sigma_tiny)
expect_run(sigma_huge_warns "warning: --sigma 1e\\+300 with d_hex .*the energy is flat" ${RUN_OUT}_sigma_huge "params.sigma=1e300 params.sigma_from=--sigma" run ${TETRA} -n 2 --backend serial --sigma 1e300 --no-cache --out ${RUN_OUT}_sigma_huge)
# The environment: named when it is the cause; `devices` always lists.
expect_exit_of(devices_bogus_variable 0 "warning: \\$MESHPARTICLES_DEVICE='bogus' matches no device above"
               env MESHPARTICLES_DEVICE=bogus $<TARGET_FILE:meshparticles> devices)
# The paper method without an OpenCL runtime, no device named: its default
# is the CPU twin, and says why; a device named stays an error (exit 3).
expect_run_of(run_paper_without_runtime "particles: .*converged" ${RUN_OUT}_no_runtime "params.method=paper params.backend=serial-field params.backend_from~pocl-opencl-icd"
               env -u MESHPARTICLES_DEVICE OCL_ICD_VENDORS=${CMAKE_CURRENT_BINARY_DIR}/no-such-vendors-dir
               $<TARGET_FILE:meshparticles> run ${TETRA} -n 2 --method paper --no-cache --out ${RUN_OUT}_no_runtime)
expect_exit_of(run_paper_device_without_runtime 3 "no OpenCL platform found"
               env MESHPARTICLES_DEVICE=pocl OCL_ICD_VENDORS=${CMAKE_CURRENT_BINARY_DIR}/no-such-vendors-dir
               $<TARGET_FILE:meshparticles> run ${TETRA} -n 2 --method paper --no-cache --out ${RUN_OUT}_device_without_runtime)
expect_exit_of(run_bogus_variable 2 "no OpenCL device matches \\$MESHPARTICLES_DEVICE='bogus'"
               env MESHPARTICLES_DEVICE=bogus $<TARGET_FILE:meshparticles> run ${TETRA} -n 2 --method paper --out ${RUN_OUT}_run_bogus_variable)
expect_exit_of(bad_pocl_cache 3 "\\$POCL_CACHE_DIR='/proc/no-such-dir' cannot be made"
               env "MESHPARTICLES_DEVICE=Portable Computing Language" POCL_CACHE_DIR=/proc/no-such-dir
               $<TARGET_FILE:meshparticles> devices)
expect_run_of(no_cache_ignores_tmpdir "converged" ${RUN_OUT}_tmpdir "params.n=2 params.backend=serial distances.from_cache=false"
               env -u HOME -u XDG_CACHE_HOME -u XDG_CONFIG_HOME TMPDIR=/nonexistent
               $<TARGET_FILE:meshparticles> run ${TETRA} -n 2 --backend serial --no-cache --out ${RUN_OUT}_tmpdir)
expect_exit_of(cache_without_tmpdir_warns 0 "warning: no cache directory: .*\\$TMPDIR='/nonexistent' is not a directory"
               env -u HOME -u XDG_CACHE_HOME TMPDIR=/nonexistent $<TARGET_FILE:meshparticles> geodesics ${TETRA})
# Destinations checked before the work, with the system's reason.
expect_exit(out_is_directory 2 "${CMAKE_CURRENT_BINARY_DIR}: cannot write: it is a directory" geodesics ${TETRA} --source 0 --out ${CMAKE_CURRENT_BINARY_DIR})
expect_exit(sweep_csv_in_proc 2 "/proc/x: cannot write to /proc: " sweep ${TETRA} -n 2 --csv /proc/x)
expect_exit(bench_csv_in_proc 2 "/proc/x: cannot write to /proc: " bench --case tetrahedron:2 --backend serial --csv /proc/x)
expect_exit(sweep_save_unwritable 2 "cannot create tuning file directory /proc/x: " sweep ${TETRA} -n 2 --save --tuning-file /proc/x/tuning.json)
expect_exit(cache_dir_unwritable 0 "warning: cannot create cache directory /proc/x: .* not cached" geodesics ${TETRA} --cache-dir /proc/x)
# A run never replaces a directory holding files it did not write.
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/cli_foreign_out)
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/cli_foreign_out/notes.txt "the user's own\n")
expect_exit(run_foreign_out 2 "output directory .*cli_foreign_out holds notes\\.txt, which a run did not write" run ${TETRA} -n 2 --out ${CMAKE_CURRENT_BINARY_DIR}/cli_foreign_out)
# A tuning file with a fractional size or an empty class is named in a warning, in run and in bench.
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/cli_fractional_tuning.json
     "{\"version\": 1, \"entries\": [{\"device\": \"d\", \"kernel\": \"tiled\", \"size_class\": \"n<=64\", \"wg\": 32.7, \"tile\": 8}]}")
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/cli_empty_class_tuning.json
     "{\"version\": 1, \"entries\": [{\"device\": \"d\", \"kernel\": \"tiled\", \"size_class\": \"\", \"wg\": 32, \"tile\": 8}]}")
expect_run(run_fractional_tuning "warning: tuning file .* is not readable \\(wg 32.7 is not a whole number above 0\\)" ${RUN_OUT}_fractional_tuning "params.backend=tiled params.sizes_from~built-in" run ${TETRA} -n 2 --backend tiled --no-cache --tuning-file ${CMAKE_CURRENT_BINARY_DIR}/cli_fractional_tuning.json --out ${RUN_OUT}_fractional_tuning)
expect_exit(bench_empty_class_tuning 0 "warning: tuning file .* is not readable \\(size class \"\" is not n<=N" bench --case tetrahedron:2 --backend tiled --iterations 1 --no-cache --tuning-file ${CMAKE_CURRENT_BINARY_DIR}/cli_empty_class_tuning.json)
# bench --quality once on the smallest case: the sanitizer stage runs it (it read freed memory once).
# Its table: each placement, and both backends' default runs at the serial energy.
add_test(NAME cli.bench_quality_small
         COMMAND bash -o pipefail -c "\"$0\" bench --quality --case tetrahedron:2 --backend serial,serial-field -q | tee /dev/stderr | grep -Ezq 'tetrahedron \\(4 vertices\\), n=2.*farthest .*default +serial +[0-9]+ .*default +serial-field +[0-9]+ .* [+]0[.]0000%'" $<TARGET_FILE:meshparticles>)
set_tests_properties(cli.bench_quality_small PROPERTIES LABELS fast)
# --strict refuses what is kept by default, with the old one-line messages.
expect_exit(strict_nonmanifold_edge 2 "nonmanifold_edge\\.off: non-manifold edge 0-1 is shared by more than two faces" info ${DATA}/nonmanifold_edge.off --strict)
expect_exit(strict_nonmanifold_vertex 2 "nonmanifold_vertex\\.off: non-manifold vertex 0" run ${DATA}/nonmanifold_vertex.off -n 2 --strict --out ${RUN_OUT}_strict_nonmanifold_vertex)
# Local distances: the backends that stream table rows say what works instead.
expect_exit(local_on_naive 2 "the naive backend streams rows of the dense distance table: use --distances dense" run ${TORUS} -n 8 --backend naive --distances local --out ${RUN_OUT}_local_on_naive)
expect_exit(local_field_half 2 "--weights half applies to the field backend on the dense table" run ${TORUS} -n 8 --backend field --weights half --distances local --out ${RUN_OUT}_local_field_half)
expect_run(run_local_field "particles: [0-9]+ done in .*converged" ${RUN_OUT}_local_field "params.n=64 params.backend=field distances.store=local" run ${TORUS} -n 64 --backend field --distances local --out ${RUN_OUT}_local_field)
expect_exit(cutoff_under_one 2 "--cutoff 0.5 is under one hexagonal spacing" run ${TORUS} -n 8 --backend serial-field --distances local --cutoff 0.5 --out ${RUN_OUT}_cutoff_under_one)
expect_exit(cutoff_with_dense 2 "--cutoff applies to --distances local and auto" run ${TORUS} -n 8 --distances dense --cutoff 6 --out ${RUN_OUT}_cutoff_with_dense)
expect_run(run_local "particles: [0-9]+ done in .*converged" ${RUN_OUT}_local "params.n=64 params.backend=serial-field distances.store=local" run ${TORUS} -n 64 --backend serial-field --distances local --out ${RUN_OUT}_local)
expect_exit(quality_cutoff_with_dense 2 "--cutoff applies to --distances local and auto" quality ${TORUS} ${PARTICLES_DATA}/blank_lines.particles --distances dense --cutoff 6)
# Large meshes for benchmarks: made at about a given size, never under a committed mesh's name.
expect_exit_of(generate_vertices 0 "wrote .*sphere_1002\\.off \\(1002 vertices, 2000 triangles\\)"
               bash -c "rm -f ${CMAKE_CURRENT_BINARY_DIR}/generated_large/sphere_1002.off && \"$0\" generate sphere --vertices 1000 --out-dir ${CMAKE_CURRENT_BINARY_DIR}/generated_large && head -n 2 ${CMAKE_CURRENT_BINARY_DIR}/generated_large/sphere_1002.off | tr '\\n' ' ' | grep -q '^OFF 1002 2000 '" $<TARGET_FILE:meshparticles>)
expect_exit(generate_vertices_torus 2 "--vertices applies to sphere and atrium, not torus" generate torus --vertices 1000 --out-dir ${CMAKE_CURRENT_BINARY_DIR}/generated_large)
expect_exit(generate_vertices_no_name 2 "--vertices needs the meshes to make at that size" generate --vertices 1000 --out-dir ${CMAKE_CURRENT_BINARY_DIR}/generated_large)
# batch: a population with a broken file, a resume after kill -9, and (when
# built with MPI) three ranks equal to one process, a rank killed then resumed
# (tests/batch_outputs.sh says what each checks).
function(batch_test mode labels)
  add_test(NAME cli.batch_${mode}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/batch_outputs.sh ${mode} $<TARGET_FILE:meshparticles>
                   ${PROJECT_SOURCE_DIR}/meshes ${DATA} ${CMAKE_CURRENT_BINARY_DIR}/batch_${mode} ${ARGN})
  # A rank that hangs (seen under heavy load) fails in minutes, not at ctest's default of 25.
  set_tests_properties(cli.batch_${mode} PROPERTIES LABELS "${labels}" PROCESSORS 2 TIMEOUT 300)
endfunction()
batch_test(broken "fast;device")
# A second batch into the --out of one in progress (the shim stops the first).
add_test(NAME cli.batch_busy_output
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/busy_output.sh $<TARGET_FILE:meshparticles> $<TARGET_FILE:kill_at_rename_shim>
                 ${PROJECT_SOURCE_DIR}/meshes ${CMAKE_CURRENT_BINARY_DIR}/batch_busy_output)
set_tests_properties(cli.batch_busy_output PROPERTIES LABELS "fast;device" TIMEOUT 120)
# quality of a run's own particles gives report.json's figures, on every committed mesh, a sphere far
# from the origin and a thin tube; on coincident sheets run, report.json and quality say why not.
add_test(NAME cli.own_figures
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/own_figures.sh $<TARGET_FILE:meshparticles> ${PROJECT_SOURCE_DIR}/meshes
                 ${CMAKE_CURRENT_BINARY_DIR}/own_figures)
set_tests_properties(cli.own_figures PROPERTIES LABELS slow TIMEOUT 600)
# The mesh digest in a batch's report.json is the read bytes', whatever happens to the file after.
add_library(replace_after_read_shim SHARED replace_after_read_shim.cpp)
target_link_libraries(replace_after_read_shim PRIVATE ${CMAKE_DL_LIBS})
add_test(NAME cli.batch_mesh_digest
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/batch_mesh_digest.sh $<TARGET_FILE:meshparticles>
                 $<TARGET_FILE:replace_after_read_shim> ${PROJECT_SOURCE_DIR}/meshes
                 ${CMAKE_CURRENT_BINARY_DIR}/batch_mesh_digest)
set_tests_properties(cli.batch_mesh_digest PROPERTIES LABELS "fast;device" TIMEOUT 120)
# The same for run and model (stopped as they put their set in place).
add_test(NAME cli.run_model_busy_output
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/busy_run_model.sh $<TARGET_FILE:meshparticles> $<TARGET_FILE:kill_at_rename_shim>
                 ${PROJECT_SOURCE_DIR}/meshes ${CMAKE_CURRENT_BINARY_DIR}/run_model_busy_output)
set_tests_properties(cli.run_model_busy_output PROPERTIES LABELS "fast;device" TIMEOUT 120)
batch_test(resume "slow;device")
if(MPI_CXX_FOUND)
  batch_test(mpi "slow;device" ${MPIEXEC_EXECUTABLE})
  batch_test(mpi_kill "slow;device" ${MPIEXEC_EXECUTABLE})
else()
  message(STATUS "MPI not found: cli.batch_mpi and cli.batch_mpi_kill are not registered")
endif()
expect_exit(batch_no_mesh 2 "folder .*holds no mesh file" batch ${CMAKE_CURRENT_SOURCE_DIR}/data/particles --out ${CMAKE_CURRENT_BINARY_DIR}/batch_no_mesh)
expect_exit(batch_n_and_spacing 2 "--particles excludes --spacing" batch ${TORUS} -n 8 --spacing 0.1 --out ${CMAKE_CURRENT_BINARY_DIR}/batch_excludes)
# n from a density: the torus's area (15.73) over the spacing gives n; the summary records it.
expect_exit(batch_spacing 0 "\\[1/1\\] torus: ok, 1500 vertices, n 202, " batch ${TORUS} --spacing 0.3 --iterations 3 --force --out ${CMAKE_CURRENT_BINARY_DIR}/batch_spacing)
# Hard edges (issue 34): empty values, empty list elements and impossible
# paths are refused while parsing; control characters stay escaped so every
# error is one line.
set(SPHERE ${PROJECT_SOURCE_DIR}/meshes/sphere.off)
# Empty arguments go through bash: CMake drops empty list elements.
function(expect_exit_shell name code pattern script)
  expect_exit_of(${name} ${code} ${pattern} bash -c "${script}" $<TARGET_FILE:meshparticles>)
endfunction()
expect_exit_shell(empty_mesh 2 "error: mesh: an empty value is not allowed" "exec \"$0\" run '' --out ${RUN_OUT}_empty_mesh")
expect_exit_shell(empty_out 2 "error: --out: an empty value is not allowed" "exec \"$0\" run ${TETRA} --out ''")
expect_exit_shell(empty_tuning_file 2 "error: --tuning-file: an empty value is not allowed" "exec \"$0\" run ${TETRA} --tuning-file '' --out ${RUN_OUT}_empty_tuning_file")
expect_exit_shell(empty_device 2 "error: --device: an empty value is not allowed" "exec \"$0\" devices --device ''")
expect_exit_shell(empty_particle_file 2 "error: particles: an empty value is not allowed" "exec \"$0\" quality ${TETRA} ''")
expect_exit_shell(empty_batch_out 2 "error: --out: an empty value is not allowed" "exec \"$0\" batch ${TETRA} --out ''")
expect_exit(empty_list_element 2 "error: --kernel: an empty element in \"naive,\"" sweep ${TETRA} --kernel naive,)
expect_exit(empty_number_element 2 "error: --wg: an empty element in \"64,,128\"" sweep ${TETRA} --wg 64,,128)
expect_exit(empty_case_element 2 "error: --case: an empty element" bench --case ,sphere:64)
expect_exit(unknown_list_name 2 "error: --backend: 'bogus' is not one of serial, " bench --backend serial-field,bogus)
expect_exit(missing_meshes_dir 2 "error: --meshes-dir: Directory does not exist" bench --meshes-dir ${CMAKE_CURRENT_BINARY_DIR}/no-such-dir)
string(REPEAT "a" 300 LONG_NAME)
expect_exit(long_path_part 2 "error: --out: a part of the path is 300 bytes, more than the 255" run ${TETRA} --out ${RUN_OUT}/${LONG_NAME})
string(REPEAT "a/" 2100 DEEP_PATH)
expect_exit(long_path 2 "error: --out: the path is [0-9]+ bytes, more than the 4095" run ${TETRA} --out ${DEEP_PATH})
expect_exit(control_characters_escaped 2 "error: bad\\\\nname\\.off: no such file$" info "bad\nname.off")
# The OpenCL runtime's environment, checked before the runtime is loaded:
# an empty $POCL_CACHE_DIR made PoCL abort (exit 134); a file made the build
# fail without naming it; a low address-space limit made it hang.
expect_exit_of(pocl_cache_empty 3 "error: \\$POCL_CACHE_DIR is set but empty" env POCL_CACHE_DIR= $<TARGET_FILE:meshparticles> run ${SPHERE} --method paper --backend field --out ${RUN_OUT}_pocl)
expect_exit_of(pocl_cache_file 3 "error: \\$POCL_CACHE_DIR='${SPHERE}' is not a directory" env POCL_CACHE_DIR=${SPHERE} $<TARGET_FILE:meshparticles> devices)
expect_run_of(pocl_cache_default_backend "particles: [0-9]+ done" ${RUN_OUT}_pocl_default "params.method=paper params.backend=serial-field params.backend_from~POCL_CACHE_DIR" env -u MESHPARTICLES_DEVICE POCL_CACHE_DIR= $<TARGET_FILE:meshparticles> run ${SPHERE} --method paper --out ${RUN_OUT}_pocl_default)
expect_exit_of(address_space_opencl 3 "error: the process's address-space or data limit \\(ulimit -v / -d: 524288 KiB\\) is under the 1024 MiB an OpenCL runtime needs.*--backend serial-field"
               bash -c "ulimit -v 524288 && exec \"$0\" run ${SPHERE} --method paper --backend field --out ${RUN_OUT}_ulimit" $<TARGET_FILE:meshparticles>)
expect_run_of(address_space_serial "particles: [0-9]+ done" ${RUN_OUT}_ulimit_serial "params.n=1024 params.backend=serial-field distances.store=dense"
               bash -c "ulimit -v 524288 && exec \"$0\" run ${SPHERE} --method paper --backend serial-field --out ${RUN_OUT}_ulimit_serial" $<TARGET_FILE:meshparticles>)
expect_exit_shell(address_space_dense_table 2 "error: [^ ]*sphere\\.off: the 4000 x 4000 distance table needs 0\\.06 GiB but the room under the address-space limit \\(ulimit -v 65536 KiB\\) holds 0\\.[0-9]+ GiB.*--distances local"
                  "ulimit -v 65536 && exec \"$0\" run ${SPHERE} --method paper --backend serial --distances dense --no-cache --out ${RUN_OUT}_ulimit_dense")
set_tests_properties(cli.address_space_opencl cli.address_space_serial cli.pocl_cache_empty PROPERTIES TIMEOUT 60)
# Under `ulimit -v` a sanitizer build cannot start (its shadow needs terabytes
# of address space): label `rlimit`, which scripts/sanitize.sh leaves out.
set_tests_properties(cli.address_space_opencl cli.address_space_serial cli.address_space_dense_table
                     PROPERTIES LABELS "fast;device;rlimit")
# What a run decides does not hang on the machine's free memory, or the run
# says so (the distance store auto picks; spread's working mesh cap).
add_test(NAME cli.machine_rules COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/machine_rules.sh $<TARGET_FILE:meshparticles> ${SPHERE}
                                        ${CMAKE_CURRENT_BINARY_DIR}/machine_rules)
set_tests_properties(cli.machine_rules PROPERTIES LABELS "fast;rlimit" TIMEOUT 300)
# Files that are not regular files (FIFOs) refused at once by every reader.
add_test(NAME cli.input_files COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/input_files.sh $<TARGET_FILE:meshparticles> ${TETRA}
                                      ${CMAKE_CURRENT_BINARY_DIR}/input_files)
set_tests_properties(cli.input_files PROPERTIES LABELS "fast;device" TIMEOUT 120)
# A shape model of corresponding particle files (docs/CORRESPONDENCE.md).
add_test(NAME cli.shape_model COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/shape_model.sh $<TARGET_FILE:meshparticles>
                                      ${CMAKE_CURRENT_BINARY_DIR}/shape_model)
set_tests_properties(cli.shape_model PROPERTIES LABELS fast)
# correspond: a mesh and three copies moved, turned, scaled (one renumbered, one rounded):
# every particle where it lies on the mesh (within 1% of the spacing) on each copy.
add_test(NAME cli.correspond COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/correspond.sh $<TARGET_FILE:meshparticles>
                                     ${PROJECT_SOURCE_DIR}/meshes/atrium.off ${CMAKE_CURRENT_BINARY_DIR}/correspond)
# About 20 s here, 150 s under the sanitizers: slow (over about 10 s).
set_tests_properties(cli.correspond PROPERTIES LABELS slow)
# The same with the template moved by the smoothed displacement (the
# default is the deformation graph); an unknown --deformation refused.
add_test(NAME cli.correspond_smooth COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/correspond.sh $<TARGET_FILE:meshparticles>
                                            ${PROJECT_SOURCE_DIR}/meshes/atrium.off ${CMAKE_CURRENT_BINARY_DIR}/correspond_smooth
                                            --deformation smooth)
set_tests_properties(cli.correspond_smooth PROPERTIES LABELS slow TIMEOUT 600)
expect_exit(correspond_unknown_deformation 2 "--deformation: bend not in .smooth,graph." correspond
            ${PROJECT_SOURCE_DIR}/meshes/atrium.off ${PROJECT_SOURCE_DIR}/meshes/atrium.off --out ${CMAKE_CURRENT_BINARY_DIR}/cli_unknown_deformation
            --deformation bend)
# correspond on a population with a known correspondence (issue 31's
# yardstick, scripts/correspondence_error.py), against batch.
add_test(NAME cli.correspond_population COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/correspond_population.sh
                                                $<TARGET_FILE:meshparticles> ${PROJECT_SOURCE_DIR}/scripts
                                                ${CMAKE_CURRENT_BINARY_DIR}/correspond_population)
set_tests_properties(cli.correspond_population PROPERTIES LABELS slow TIMEOUT 300)  # about 12 s here
# correspond shared among MPI ranks: the outputs of one process, byte for byte.
function(correspond_share_test mode)
  add_test(NAME cli.correspond_${mode}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/correspondence/mpi_shape_share_test.sh ${mode} $<TARGET_FILE:meshparticles>
                   ${CMAKE_CURRENT_BINARY_DIR}/correspond_${mode} ${ARGN})
  set_tests_properties(cli.correspond_${mode} PROPERTIES LABELS slow PROCESSORS 2 TIMEOUT 600)
endfunction()
# correspond killed at every write, its checkpoint damaged, a second run into its --out.
add_library(kill_at_rename_shim SHARED kill_at_rename_shim.cpp)
target_link_libraries(kill_at_rename_shim PRIVATE ${CMAKE_DL_LIBS})
add_test(NAME cli.correspond_checkpoint
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/correspond_checkpoint.sh $<TARGET_FILE:meshparticles>
                 $<TARGET_FILE:kill_at_rename_shim> ${CMAKE_CURRENT_BINARY_DIR}/correspond_checkpoint)
set_tests_properties(cli.correspond_checkpoint PROPERTIES LABELS slow TIMEOUT 900)
# correspond and batch over an older complete set: killed at every write, a
# full disk, leftovers of another host or PID namespace (docs/OUTPUTS.md).
add_test(NAME cli.replaced_outputs
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/replaced_outputs.sh $<TARGET_FILE:meshparticles>
                 $<TARGET_FILE:kill_at_rename_shim> $<TARGET_FILE:full_disk_shim> ${PROJECT_SOURCE_DIR}/meshes
                 ${CMAKE_CURRENT_BINARY_DIR}/replaced_outputs)
set_tests_properties(cli.replaced_outputs PROPERTIES LABELS "slow;device" TIMEOUT 600)
if(MPI_CXX_FOUND)
  correspond_share_test(mpi ${MPIEXEC_EXECUTABLE})
else()
  message(STATUS "MPI not found: cli.correspond_mpi is not registered")
endif()
# File and folder names that are not UTF-8 (issue 50, item 13): valid JSON and messages, the bytes escaped.
add_test(NAME cli.non_utf8_paths COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/non_utf8_paths.sh $<TARGET_FILE:meshparticles> ${TETRA}
                                         ${CMAKE_CURRENT_BINARY_DIR}/non_utf8_paths)
set_tests_properties(cli.non_utf8_paths PROPERTIES LABELS "fast;device" TIMEOUT 120)
