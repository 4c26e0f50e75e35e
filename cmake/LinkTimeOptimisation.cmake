# Link-time optimisation of the programs whose speed users see (scenfuzz, simulation_benchmark) in
# optimised GCC builds. A simulation step calls across files at every actor (into the lane
# followers, the collision world, the trace's columns); linked whole, those calls inline as if the
# code were in one file: about 5 % fewer instructions in a simulation, and the same results bit
# for bit (docs/performance.md, "Link-time optimisation"). The libraries' objects carry machine
# code as well as GCC's intermediate code ("fat" objects), so that the test programs link them as
# they always did: linking every test program whole would double the CI's build.
option(SCENFUZZ_LTO "Link scenfuzz and simulation_benchmark whole (GCC, optimised builds)" ON)

set(SCENFUZZ_LTO_ACTIVE OFF)
if(SCENFUZZ_LTO
   AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU"
   AND CMAKE_BUILD_TYPE MATCHES "^(Release|RelWithDebInfo|MinSizeRel)$")
  include(CheckIPOSupported)
  check_ipo_supported(RESULT SCENFUZZ_LTO_ACTIVE OUTPUT scenfuzz_lto_error LANGUAGES CXX)
  if(NOT SCENFUZZ_LTO_ACTIVE)
    message(WARNING "scenfuzz: no link-time optimisation (${scenfuzz_lto_error})")
  endif()
endif()

# Compiles the `libraries` into fat objects and links the `programs` whole.
function(scenfuzz_link_time_optimisation)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "" "LIBRARIES;PROGRAMS")
  if(NOT SCENFUZZ_LTO_ACTIVE)
    return()
  endif()
  foreach(target IN LISTS arg_LIBRARIES arg_PROGRAMS)
    target_compile_options(${target} PRIVATE -flto=auto -ffat-lto-objects)
  endforeach()
  foreach(target IN LISTS arg_PROGRAMS)
    target_link_options(${target} PRIVATE -flto=auto)
  endforeach()
endfunction()
