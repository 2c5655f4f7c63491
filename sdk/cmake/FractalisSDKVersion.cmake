# The SDK's version: the scene ABI it builds against (fractalis/abi.h: FR_ABI_VERSION_MAJOR and
# _MINOR), plus a patch number. One place, read by the package's version check and by
# sdk/CMakeLists.txt.
set(FRACTALIS_SDK_VERSION 1.0.0)
