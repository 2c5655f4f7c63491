# find_package(FractalisSDK 1.0) for third-party scenes. Gives:
#   Fractalis::sdk          an imported target with the C ABI headers (fractalis/fractalis.h)
#   fractalis_add_scene()   builds a scene plugin (see FractalisScene.cmake)
#   FRACTALIS_SDK_VERSION   the SDK version (the scene ABI it builds against)
#   FRACTALIS_SDK_OPENCL_DIR  the OpenCL side: prelude.cl and the fr/*.cl DE library, for reading
#                           and editor tooling (the host compiles its own copy)
#   FRACTALIS_SDK_DOC_DIR   the scene guide
# Found from an installed SDK (<prefix>/lib/cmake/FractalisSDK, Debian's multiarch
# <prefix>/lib/<triplet>/cmake/FractalisSDK) and from the source tree (<source>/sdk/cmake).
include("${CMAKE_CURRENT_LIST_DIR}/FractalisSDKVersion.cmake")

# The include folder is the nearest parent's include/ that holds fractalis/abi.h: sdk/include in
# the source tree, <prefix>/include when installed (two or three levels above lib/).
unset(FRACTALIS_SDK_INCLUDE_DIR)
foreach(_up ".." "../../.." "../../../..")
  get_filename_component(_root "${CMAKE_CURRENT_LIST_DIR}/${_up}" ABSOLUTE)
  if(EXISTS "${_root}/include/fractalis/abi.h")
    set(FRACTALIS_SDK_INCLUDE_DIR "${_root}/include")
    if(EXISTS "${_root}/share/fractalis/opencl/prelude.cl")  # installed
      set(FRACTALIS_SDK_OPENCL_DIR "${_root}/share/fractalis/opencl")
      set(FRACTALIS_SDK_DOC_DIR "${_root}/share/doc/fractalis-sdk")
    else()  # the source tree: sdk/cmake/../../kernels
      get_filename_component(FRACTALIS_SDK_OPENCL_DIR "${_root}/../kernels" ABSOLUTE)
      set(FRACTALIS_SDK_DOC_DIR "${_root}/docs")
    endif()
    break()
  endif()
endforeach()
unset(_up)
unset(_root)
if(NOT FRACTALIS_SDK_INCLUDE_DIR)
  set(FractalisSDK_FOUND FALSE)
  set(FractalisSDK_NOT_FOUND_MESSAGE
      "fractalis/abi.h not found above ${CMAKE_CURRENT_LIST_DIR}: a broken SDK install")
  return()
endif()

if(NOT TARGET Fractalis::sdk)
  add_library(Fractalis::sdk INTERFACE IMPORTED)
  set_target_properties(Fractalis::sdk PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${FRACTALIS_SDK_INCLUDE_DIR}")
endif()
include("${CMAKE_CURRENT_LIST_DIR}/FractalisScene.cmake")
