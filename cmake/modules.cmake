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

# Profile-guided optimisation (scripts/build.sh release): "generate" builds an
# instrumented program that writes branch and call counts to RT_PGO_DIR when it
# exits; "use" compiles with those counts. Object paths are taken relative to
# the build folder (-fprofile-prefix-path), so an instrumented build in one
# folder feeds the real build in another. Functions the training jobs never ran
# are optimised as without a profile (-fprofile-partial-training), and a
# profile older than the source only costs speed, so it warns instead of failing.
set(RT_PGO "" CACHE STRING "Profile-guided optimisation: generate, use, or empty for none")
set(RT_PGO_DIR "" CACHE PATH "Folder of the profile (.gcda files) for RT_PGO")
if(RT_PGO)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    message(FATAL_ERROR "RT_PGO needs GCC (its .gcda profile format)")
  endif()
  if(NOT RT_PGO_DIR)
    message(FATAL_ERROR "RT_PGO needs RT_PGO_DIR, the profile folder")
  endif()
  if(RT_PGO STREQUAL "generate")
    # One thread trains, so the counters need no atomic updates.
    add_compile_options(-fprofile-generate=${RT_PGO_DIR} -fprofile-update=single
                        -fprofile-prefix-path=${CMAKE_BINARY_DIR})
    add_link_options(-fprofile-generate=${RT_PGO_DIR})
  elseif(RT_PGO STREQUAL "use")
    add_compile_options(-fprofile-use=${RT_PGO_DIR} -fprofile-partial-training
                        -fprofile-prefix-path=${CMAKE_BINARY_DIR}
                        -Wno-missing-profile -Wno-error=coverage-mismatch)
  else()
    message(FATAL_ERROR "RT_PGO must be generate, use or empty, not '${RT_PGO}'")
  endif()
endif()

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
