# Sourced by CI's own builds (scripts/check-portability, scripts/sanitize, scripts/fuzz); the user's build
# (scripts/build) does not use it. ci_configure DIR [cmake args...] configures DIR with Ninja: Ninja starts a test
# program's files while a library's last files still compile, where Make waits for the whole library, so both cores
# stay busy (the sanitizer build: 462 s against about 530 s with Make, docs/reliability.md, CI). A DIR configured
# earlier with another generator is removed first: CMake cannot switch generators in place.
ci_configure() {
  local dir="$1"
  shift
  if [ -f "$dir/CMakeCache.txt" ] && ! grep -q "^CMAKE_GENERATOR:INTERNAL=Ninja$" "$dir/CMakeCache.txt"; then
    echo "ci: $dir was configured with another generator; removing it"
    rm -rf "$dir"
  fi
  cmake -G Ninja -S . -B "$dir" "$@" >/dev/null
}

# The one sanitized build (build-asan) of scripts/sanitize and scripts/fuzz: clang, ASan + UBSan at -O1 -g1 (a
# report still names the file and line), merged in unity batches, with libFuzzer's coverage instrumentation
# (-fsanitize=fuzzer-no-link) in the scene reader's library (coupling) and the fuzz target, so that the fuzz target
# links against the libraries the sanitized tests ran and the fuzz stage compiles one file instead of the libraries
# again. clang, not g++: libFuzzer is clang's, and
# clang compiled this build in about 1450 s of CPU where g++'s sanitizer build and clang's fuzzer build took about
# 2580 s together (docs/reliability.md, CI).
ci_configure_sanitized() {
  CXX=clang++ ci_configure build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DSPHSLOPE_SANITIZE=address,undefined -DSPHSLOPE_FUZZ=ON -DCMAKE_UNITY_BUILD=ON
}
