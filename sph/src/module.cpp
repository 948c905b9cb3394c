// Anchor translation unit of the particle-engine library.
namespace sph {
const char* module_name() { return "sph"; }
}  // namespace sph
