# cmake -DSG_BUILD_DIR=... -DSG_SOURCE_DIR=... -DWORK_DIR=... -DGENERATOR=... -P package_plugin_test.cmake
#
# What a third party does with shadelgraph: install it, build a plugin against
# the installed package only (find_package(shadelgraph)), and run the
# installed executable with the plugin.
cmake_minimum_required(VERSION 3.25)
foreach(var SG_BUILD_DIR SG_SOURCE_DIR WORK_DIR GENERATOR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "package_plugin_test.cmake: -D${var}=... is required")
  endif()
endforeach()

set(prefix ${WORK_DIR}/prefix)
set(build ${WORK_DIR}/build)
set(plugin ${build}/libsg_example_stripes.so)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# run(<what> COMMAND ...): runs it, fails the test with its output unless it exits 0.
function(run what)
  execute_process(${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${what} failed (${code}):\n${out}\n${err}")
  endif()
  set(run_stdout "${out}" PARENT_SCOPE)
  set(run_stderr "${err}" PARENT_SCOPE)
endfunction()

# 1. Install this build.
run("cmake --install" COMMAND ${CMAKE_COMMAND} --install ${SG_BUILD_DIR} --prefix ${prefix})
foreach(file bin/shadelgraph include/shadelgraph/plugin/plugin_api.hpp lib/cmake/shadelgraph/shadelgraphConfig.cmake)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "the installed package has no ${file}")
  endif()
endforeach()

# The material SDK's GLSL is installed, to be read, by the paths layers
# include: the umbrella and, transitively, every file it includes.
set(glsl ${prefix}/include/shadelgraph/glsl)
set(sdk_umbrella framework/plugin/shaders/material.glsl)
if(NOT EXISTS ${glsl}/${sdk_umbrella})
  message(FATAL_ERROR "the installed package has no material SDK: ${glsl}/${sdk_umbrella} is missing")
endif()
set(pending ${sdk_umbrella})
set(seen "")
while(pending)
  list(POP_FRONT pending file)
  if(file IN_LIST seen)
    continue()
  endif()
  list(APPEND seen ${file})
  # The includes GLSL sees: not those of a shared header's C++ half (#ifdef __cplusplus ... #else).
  file(STRINGS ${glsl}/${file} lines REGEX "^[ \t]*#[ \t]*(include|ifdef|else|endif)")
  set(includes "")
  set(cpp OFF)
  foreach(line IN LISTS lines)
    if(line MATCHES "^[ \t]*#[ \t]*ifdef[ \t]+__cplusplus")
      set(cpp ON)
    elseif(line MATCHES "^[ \t]*#[ \t]*(else|endif)")
      set(cpp OFF)
    elseif(NOT cpp AND line MATCHES "include")
      list(APPEND includes "${line}")
    endif()
  endforeach()
  get_filename_component(dir ${file} DIRECTORY)
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]+)[>\"].*" "\\1" path "${line}")
    if(line MATCHES "\"" AND EXISTS ${glsl}/${dir}/${path})
      cmake_path(SET path NORMALIZE "${dir}/${path}")  # quoted: beside the including file first
    endif()
    if(NOT EXISTS ${glsl}/${path})
      message(FATAL_ERROR "the installed SDK file ${file} includes ${path}, which is not installed under ${glsl}")
    endif()
    list(APPEND pending ${path})
  endforeach()
endwhile()

# 2. Build the example plugin out of tree, against the installed package only.
run("configuring plugins/example-stripes" COMMAND ${CMAKE_COMMAND}
  -S ${SG_SOURCE_DIR}/plugins/example-stripes -B ${build} -G "${GENERATOR}"
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_PREFIX_PATH=${prefix})
run("building plugins/example-stripes" COMMAND ${CMAKE_COMMAND} --build ${build})
foreach(file ${plugin} ${build}/shaders/example-stripes/stripes.glsl)
  if(NOT EXISTS ${file})
    message(FATAL_ERROR "the plugin build did not produce ${file}")
  endif()
endforeach()
# It links the installed framework libraries, and carries no copy of them.
run("readelf" COMMAND readelf -d ${plugin})
if(NOT run_stdout MATCHES "libshadelgraph_plugin\\.so")
  message(FATAL_ERROR "${plugin} does not link libshadelgraph_plugin.so:\n${run_stdout}")
endif()
run("nm" COMMAND nm -C --defined-only ${plugin})
if(run_stdout MATCHES "Registry::addLayer")
  message(FATAL_ERROR "${plugin} defines its own Registry::addLayer: it carries a copy of the framework")
endif()

# 3. The installed executable loads it: `graph` runs the whole session setup
# (plugins, scene, device) without rendering. Loading it again from its
# directory must fail (its layer is already registered), proving it loaded.
set(sg ${prefix}/bin/shadelgraph)
run("shadelgraph graph --plugin" COMMAND ${sg} graph --size 64x64 --plugin ${plugin})
if(NOT run_stderr MATCHES "plugin 'example-stripes'")
  message(FATAL_ERROR "shadelgraph graph --plugin did not report loading example-stripes:\n${run_stderr}")
endif()
run("shadelgraph graph --plugin-dir" COMMAND ${sg} graph --size 64x64 --plugin-dir ${build})
execute_process(COMMAND ${sg} graph --size 64x64 --plugin-dir ${build} --plugin ${plugin}
  RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_QUIET)
if(code EQUAL 0 OR NOT err MATCHES "material layer 'stripes'.*already registered")
  message(FATAL_ERROR "loading example-stripes twice should fail on its duplicate layer (${code}):\n${err}")
endif()

# A frame renders with the plugin loaded (the built-in materials still work).
run("shadelgraph render --plugin" COMMAND ${sg} render --size 128x128 --plugin ${plugin} -o ${WORK_DIR}/plain.png)
if(NOT EXISTS ${WORK_DIR}/plain.png)
  message(FATAL_ERROR "shadelgraph render --plugin did not write ${WORK_DIR}/plain.png")
endif()

# 4. Render the default scene with every object in the plugin's material, in
# both shading paths (the framework generates both variants from its GLSL);
# each differs from the plain render.
file(SHA256 ${WORK_DIR}/plain.png plain_hash)
foreach(mode decoupled forward)
  set(image ${WORK_DIR}/stripes-${mode}.png)
  run("shadelgraph render --plugin --material (${mode})" COMMAND ${sg} render --plugin ${plugin}
    --material example-stripes --mode ${mode} -o ${image} --size 128x128)
  if(NOT EXISTS ${image})
    message(FATAL_ERROR "shadelgraph render did not write ${image}")
  endif()
  file(SHA256 ${image} hash)
  if(hash STREQUAL plain_hash)
    message(FATAL_ERROR "${image} is the plain render: the plugin's material was not used")
  endif()
endforeach()
# 5. The out-of-tree pass plugin: a depth outline after tonemap, in its own
# frame ("outlined": the decoupled frame plus the pass). Built against the
# installed package only; in both shading modes its image differs from the
# same frame without it, and the pass is in the compiled graph.
# build_example(<name> <var>): plugins/example-<name> built against the
# installed package only; <var> is set to the plugin library.
function(build_example name var)
  set(dir ${WORK_DIR}/build-${name})
  run("configuring plugins/example-${name}" COMMAND ${CMAKE_COMMAND}
    -S ${SG_SOURCE_DIR}/plugins/example-${name} -B ${dir} -G "${GENERATOR}"
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_PREFIX_PATH=${prefix})
  run("building plugins/example-${name}" COMMAND ${CMAKE_COMMAND} --build ${dir})
  set(${var} ${dir}/libsg_example_${name}.so PARENT_SCOPE)
endfunction()

# expect_different(<a> <b> <why>): the two images differ, else the test fails saying why.
function(expect_different a b why)
  file(SHA256 ${a} a_hash)
  file(SHA256 ${b} b_hash)
  if(a_hash STREQUAL b_hash)
    message(FATAL_ERROR "${b} equals ${a}: ${why}")
  endif()
endfunction()

build_example(outline outline)
run("shadelgraph graph --frame-graph outlined" COMMAND ${sg} graph --size 64x64 --plugin ${outline} --frame-graph outlined)
if(NOT run_stdout MATCHES "outline")
  message(FATAL_ERROR "the outlined frame's graph has no outline pass:\n${run_stdout}")
endif()
foreach(mode decoupled forward)
  set(plain ${WORK_DIR}/plain-${mode}.png)
  set(outlined ${WORK_DIR}/outlined-${mode}.png)
  run("shadelgraph render (${mode})" COMMAND ${sg} render --size 128x128 --mode ${mode} -o ${plain})
  run("shadelgraph render --frame-graph outlined (${mode})" COMMAND ${sg} render --size 128x128 --mode ${mode}
    --plugin ${outline} --frame-graph outlined -o ${outlined})
  expect_different(${plain} ${outlined} "the outline pass drew nothing")
endforeach()
# 6. The out-of-tree plugin whose pass output a layer samples: ssao writes
# ao.image before shading; the material example-ao-pbr's layer ao-darken
# samples it in both variants. In both modes its image differs from the same
# frame with the plain glTF material; without the ssao pass in the frame, the
# layer's missing input is one line naming the layer and the resource.
build_example(ssao ssao)
foreach(mode decoupled forward)
  set(plain ${WORK_DIR}/ssao-plain-${mode}.png)
  set(darkened ${WORK_DIR}/ssao-ao-${mode}.png)
  run("shadelgraph render --frame-graph ssao (${mode})" COMMAND ${sg} render --size 128x128 --mode ${mode}
    --plugin ${ssao} --frame-graph ssao -o ${plain})
  run("shadelgraph render --frame-graph ssao --material example-ao-pbr (${mode})" COMMAND ${sg} render --size 128x128
    --mode ${mode} --plugin ${ssao} --frame-graph ssao --material example-ao-pbr -o ${darkened})
  expect_different(${plain} ${darkened} "the layer did not sample ao.image")
endforeach()
execute_process(COMMAND ${sg} render --size 64x64 --plugin ${ssao} --material example-ao-pbr -o ${WORK_DIR}/x.png
  RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT code EQUAL 1 OR NOT err MATCHES "material layer 'ao-darken' \\(plugin 'example-ssao'\\) samples frame resource 'ao.image'")
  message(FATAL_ERROR "a frame without the ssao pass should fail naming the layer and ao.image (${code}):\n${err}")
endif()
message(STATUS "installed package, out-of-tree plugin builds and plugin loads: OK")
