// The one translation unit that compiles tinygltf (and its JSON and base64 code).
#define TINYGLTF_IMPLEMENTATION
#include "mesh/tinygltf.h"
