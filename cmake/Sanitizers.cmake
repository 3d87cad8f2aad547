# SG_SANITIZE=ON builds everything with AddressSanitizer + UndefinedBehaviorSanitizer.
option(SG_SANITIZE "Build with ASan + UBSan" OFF)
if(SG_SANITIZE)
  # vptr checks need RTTI for every class; Debian builds glslang with -fno-rtti.
  add_compile_options(-fsanitize=address,undefined -fno-sanitize=vptr -fno-omit-frame-pointer
                      -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()
