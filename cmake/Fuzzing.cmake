# SG_FUZZ=ON: libFuzzer targets with ASan + UBSan (Debian's clang-14 and
# libclang-rt-14-dev; ./sg installs them and configures build-fuzz with them).
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "SG_FUZZ needs clang (libFuzzer): configure with CC=clang-14 CXX=clang++-14")
endif()
if(SG_SANITIZE)
  message(FATAL_ERROR "SG_FUZZ already builds with ASan + UBSan; leave SG_SANITIZE off")
endif()
include(GNUInstallDirs)

# Only what framework/scene, the scene-file loader and the CLI parser need.
find_package(glm CONFIG REQUIRED)
find_package(nlohmann_json CONFIG REQUIRED)
find_package(CLI11 CONFIG REQUIRED)
find_package(TinyGLTF CONFIG REQUIRED)
find_package(meshoptimizer CONFIG REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)

# Without a build type: optimized enough to run fast, with asserts and line
# numbers in the stack traces.
if(NOT CMAKE_BUILD_TYPE)
  add_compile_options(-O1 -g)
endif()
# Coverage instrumentation everywhere (the libraries too); the fuzzer's main is
# linked into the targets only (sg_add_fuzzer). UB aborts, so libFuzzer sees it.
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                    -fno-omit-frame-pointer)
add_link_options(-fsanitize=address,undefined)
