# Every dependency is a Debian package; ./sg installs them (see sg, DEBIAN_PACKAGES).
find_package(Vulkan REQUIRED)
find_package(glslang CONFIG REQUIRED)
find_package(glm CONFIG REQUIRED)
find_package(nlohmann_json CONFIG REQUIRED)
find_package(CLI11 CONFIG REQUIRED)
find_package(TinyGLTF CONFIG REQUIRED)
find_package(meshoptimizer CONFIG REQUIRED)  # welding and mesh analysis at load (scene)
find_package(PkgConfig REQUIRED)
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
find_package(Threads REQUIRED)
# The viewer (shadelgraph view): GLFW windows, Dear ImGui with its GLFW and
# Vulkan backends (Debian builds them into libimgui.a).
find_package(glfw3 CONFIG REQUIRED)
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
if(SG_BUILD_TESTS)
  find_package(GTest CONFIG REQUIRED)
  # SPIR-V reflection for the test that checks pass shaders against their declarations.
  pkg_check_modules(SpirvCross REQUIRED IMPORTED_TARGET spirv-cross-c-shared)
endif()
if(SG_BUILD_BENCHMARKS)
  find_package(benchmark CONFIG REQUIRED)
endif()
