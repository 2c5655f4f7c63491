# find_package(FractalisSDK) for third-party scenes: gives fractalis_add_scene().
get_filename_component(FRACTALIS_SDK_INCLUDE_DIR "${CMAKE_CURRENT_LIST_DIR}/../../../include" ABSOLUTE)
include("${CMAKE_CURRENT_LIST_DIR}/FractalisScene.cmake")
