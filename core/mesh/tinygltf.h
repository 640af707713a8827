// tinygltf as Tessera configures it, for the glTF reader (mesh/) and the GLB writer (export/):
// no image decoding or encoding (Tessera reads geometry only and writes no textures), no external
// images. The implementation is compiled once, in tinygltf.cpp.
#pragma once

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
