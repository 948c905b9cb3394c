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
