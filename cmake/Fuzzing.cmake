# SCENFUZZ_FUZZ=ON: a separate build (preset `fuzz`, scripts/fuzz.sh) in which everything is
# compiled with clang's coverage instrumentation, AddressSanitizer and UndefinedBehaviorSanitizer.
# Only the front end and the fuzz harnesses are built, so no third-party package is needed.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "SCENFUZZ_FUZZ=ON needs clang (libFuzzer); configure with "
                      "-DCMAKE_CXX_COMPILER=clang++ or use `cmake --preset fuzz`")
endif()

set(SCENFUZZ_SANITIZERS address,undefined)
add_compile_options(-fsanitize=fuzzer-no-link,${SCENFUZZ_SANITIZERS}
                    -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g)
add_link_options(-fsanitize=${SCENFUZZ_SANITIZERS} -fno-sanitize-recover=undefined)
