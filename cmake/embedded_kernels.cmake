# kernels/ travels inside the binary: fractalis_embed_kernels(VAR) adds the command that turns
# every kernel file into one C source (sdk/cmake/fractalis_embed.cmake) in the calling folder's
# build folder, and sets VAR to that source's path (render/kernel_sources.cpp reads its table).
# The host uses it, and so does the Windows build's part that is ported so far.
set(fractalis_kernel_files frame_constants.h wide_lanes.cl prelude.cl eval_counts.cl rays.cl march.cl cone.cl
    normals.cl shadow.cl ao.cl glow.cl fog.cl lens.cl reflect.cl lights.cl environment.cl shade.cl
    film.cl render.cl
    material.cl area_lights.cl path.cl post.cl denoise.cl probe.cl material_probe.cl
    de/primitives.cl de/operators.cl de/folds.cl de/powers.cl de/mandelbulb.cl de/menger.cl de/sierpinski.cl
    de/julia.cl de/palette.cl de/mandelbox.cl de/kifs.cl de/jerusalem.cl de/kleinian.cl
    de/hypercomplex.cl de/cantor.cl de/kali.cl de/recursive.cl
    de/hybrid.cl de/staging.cl de/mandelbulber.cl de/dd.cl de/mandelbox_dd.cl de/menger_dd.cl
    de/mandelbulb_dd.cl de/dd_folds.cl de/hybrid_dd.cl
    dd_selftest.cl dd_relative.cl)

function(fractalis_embed_kernels out_var)
  set(kernel_paths "")
  set(kernel_symbols "")
  foreach(f ${fractalis_kernel_files})
    list(APPEND kernel_paths "${PROJECT_SOURCE_DIR}/kernels/${f}")
    string(MAKE_C_IDENTIFIER "fr_kernel_${f}" sym)
    list(APPEND kernel_symbols "${sym}")
  endforeach()
  list(JOIN kernel_paths "|" kernel_paths_arg)
  list(JOIN kernel_symbols "|" kernel_symbols_arg)
  list(JOIN fractalis_kernel_files "|" kernel_names_arg)
  set(embedded "${CMAKE_CURRENT_BINARY_DIR}/embedded_kernels.c")
  add_custom_command(
    OUTPUT "${embedded}"
    COMMAND ${CMAKE_COMMAND} "-DOUTPUT=${embedded}" "-DINPUTS=${kernel_paths_arg}"
            "-DSYMBOLS=${kernel_symbols_arg}" -DTABLE=fr_embedded_kernels
            "-DNAMES=${kernel_names_arg}" -P "${PROJECT_SOURCE_DIR}/sdk/cmake/fractalis_embed.cmake"
    DEPENDS ${kernel_paths} "${PROJECT_SOURCE_DIR}/sdk/cmake/fractalis_embed.cmake"
    COMMENT "Embedding kernels/"
    VERBATIM)
  set(${out_var} "${embedded}" PARENT_SCOPE)
endfunction()
