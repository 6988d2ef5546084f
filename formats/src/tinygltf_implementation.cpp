// tinygltf's code, compiled here (Debian ships the header; compiling it ourselves lets the fuzz build instrument
// it too). formats/CMakeLists.txt defines TINYGLTF_NO_STB_IMAGE and friends for every file of the library: images
// are never decoded, a character's look is its base colour.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
