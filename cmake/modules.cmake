# Helpers that give every module the same shape: one static library target
# rt_<name> with alias rt::<name>, the repository root as include path, and the
# shared warning set.

add_library(rt_warnings INTERFACE)
target_compile_options(rt_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast
  $<$<BOOL:${RT_WERROR}>:-Werror>)

# Link a shared library only where a program uses a symbol of it: rtrace takes
# the Radiance-picture reader from rt_image but not its OpenEXR code, so it
# should not need OpenEXR, Imath, Iex and IlmThread installed to start
# (Debian's linker keeps every library named on the command line by default).
add_link_options(LINKER:--as-needed)

if(RT_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer
                      -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()

# rt_add_module(name SOURCES a.cpp b.cpp DEPS rt::core [PRIVATE_DEPS x])
function(rt_add_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(rt_${name} STATIC ${ARG_SOURCES})
  add_library(rt::${name} ALIAS rt_${name})
  target_include_directories(rt_${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(rt_${name} PUBLIC ${ARG_DEPS} PRIVATE rt_warnings ${ARG_PRIVATE_DEPS})
endfunction()

# rt_add_tool(name SOURCES main.cpp DEPS rt::scene): a program in build/bin/.
function(rt_add_tool name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} rt_warnings)
endfunction()
