# sg_set_warnings(target): the project's warning set, errors-free but strict.
function(sg_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
    -Wnon-virtual-dtor -Wcast-align -Wunused -Woverloaded-virtual
    -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough
    # `VkFooInfo info{VK_STRUCTURE_TYPE_FOO}` zero-fills the rest on purpose.
    -Wno-missing-field-initializers)
  if(SG_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
option(SG_WERROR "Treat warnings in our code as errors" OFF)
