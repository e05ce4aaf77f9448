// The one translation unit that compiles tinygltf's implementation (see gltf_config.hpp).
#define TINYGLTF_IMPLEMENTATION
#include "gltf_config.hpp"
