# fractalis_add_scene(<target> SOURCES <c files...> DE_SOURCE <file.cl>
#                     [SURFACE_SOURCE <file.cl>] [OUTPUT_DIRECTORY <dir>])
#
# Builds a Fractalis scene plugin: a MODULE library named <target>.so (<target>.dll on Windows)
# whose only exported symbol is fractalis_scene_entry, linked so that a missing symbol fails at
# build time, not at load time (on Linux with -z defs; libm is linked for you). The OpenCL files are embedded as
#   extern const char fr_de_source[];       (DE_SOURCE)
#   extern const char fr_surface_source[];  (SURFACE_SOURCE, if given)
# for the scene descriptor's de_source and surface_source fields.
set(FRACTALIS_SDK_CMAKE_DIR "${CMAKE_CURRENT_LIST_DIR}")
if(NOT FRACTALIS_SDK_INCLUDE_DIR)
  # In the source tree; an installed SDK's FractalisSDKConfig.cmake sets this first.
  get_filename_component(FRACTALIS_SDK_INCLUDE_DIR "${CMAKE_CURRENT_LIST_DIR}/../include" ABSOLUTE)
endif()

function(fractalis_add_scene target)
  cmake_parse_arguments(ARG "" "DE_SOURCE;SURFACE_SOURCE;OUTPUT_DIRECTORY" "SOURCES" ${ARGN})
  if(NOT ARG_SOURCES OR NOT ARG_DE_SOURCE)
    message(FATAL_ERROR "fractalis_add_scene(${target}): SOURCES and DE_SOURCE are required")
  endif()
  get_filename_component(de_path "${ARG_DE_SOURCE}" ABSOLUTE)
  set(inputs "${de_path}")
  set(symbols "fr_de_source")
  if(ARG_SURFACE_SOURCE)
    get_filename_component(surface_path "${ARG_SURFACE_SOURCE}" ABSOLUTE)
    string(APPEND inputs "|${surface_path}")
    string(APPEND symbols "|fr_surface_source")
  endif()
  set(embedded "${CMAKE_CURRENT_BINARY_DIR}/${target}_sources.c")
  add_custom_command(
    OUTPUT "${embedded}"
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${embedded} -DINPUTS=${inputs} -DSYMBOLS=${symbols}
            -P "${FRACTALIS_SDK_CMAKE_DIR}/fractalis_embed.cmake"
    DEPENDS "${de_path}" ${surface_path} "${FRACTALIS_SDK_CMAKE_DIR}/fractalis_embed.cmake"
    COMMENT "Embedding the OpenCL sources of ${target}"
    VERBATIM)
  add_library(${target} MODULE ${ARG_SOURCES} "${embedded}")
  target_include_directories(${target} PRIVATE "${FRACTALIS_SDK_INCLUDE_DIR}")
  set_target_properties(${target} PROPERTIES
    PREFIX ""
    C_VISIBILITY_PRESET hidden
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  if(ARG_OUTPUT_DIRECTORY)
    set_target_properties(${target} PROPERTIES LIBRARY_OUTPUT_DIRECTORY "${ARG_OUTPUT_DIRECTORY}")
  endif()
  # ELF (Linux): export the entry alone, and refuse undefined symbols at link time. A Windows
  # DLL exports what FR_EXPORT marks (__declspec(dllexport)) and cannot leave symbols undefined.
  if(NOT WIN32 AND NOT APPLE)
    target_link_options(${target} PRIVATE
      "LINKER:--version-script=${FRACTALIS_SDK_CMAKE_DIR}/scene.map" "LINKER:-z,defs")
  endif()
  # MinGW: the GCC runtime (libgcc, libstdc++, winpthread) linked into the DLL, which otherwise
  # fails to load on a PC without those DLLs beside fractalis.exe.
  if(MINGW)
    target_link_options(${target} PRIVATE -static)
  endif()
  # -z defs makes every undefined symbol an error, libm's (sin, pow, ...) included: link it.
  if(UNIX AND NOT APPLE)
    target_link_libraries(${target} PRIVATE m)
  endif()
endfunction()
