// tinygltf (Debian libtinygltf-dev, header-only here) as hullkit uses it: geometry only. Images
// are never decoded or read (no stb_image), and tinygltf never touches the file system itself:
// external buffers come through the callbacks gltf.cpp gives it (TINYGLTF_NO_FS), so the same code
// builds natively and for WebAssembly. gltf_library.cpp compiles the implementation, once.
#pragma once

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_NO_FS
// No exceptions from tinygltf's JSON parse (the WebAssembly build cannot catch them): gltf.cpp checks
// the JSON first, with a message saying where it breaks, the same natively and in wasm.
#define TINYGLTF_NOEXCEPTION

// tinygltf 2.7's writer uses std::ofstream even without a file system (TINYGLTF_NO_FS) and does not
// include <fstream> then.
#include <fstream>
#include <sstream>

#include <tiny_gltf.h>
