#pragma once

// Where the coupling tests find the project's scene files and the sphslope program.
// The paths are compiled into one file (test_paths.cpp), not into each test as string literals: GCC 12 inlines
// a std::string concatenation with a literal of known length and, for some lengths of the build folder's path,
// reports a false out-of-bounds copy (-Warray-bounds), which fails a build with warnings as errors.
namespace test_paths {

// The project's source folder (cases/, tests/golden/).
const char* source_dir();
// The sphslope program built with the tests.
const char* binary();

}  // namespace test_paths
