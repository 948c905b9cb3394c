#include "test_paths.hpp"

namespace test_paths {

// SPHSLOPE_SOURCE_DIR and SPHSLOPE_BINARY are defined for this file alone (tests/CMakeLists.txt).
const char* source_dir() { return SPHSLOPE_SOURCE_DIR; }
const char* binary() { return SPHSLOPE_BINARY; }

}  // namespace test_paths
