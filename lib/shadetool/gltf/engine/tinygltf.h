// tinygltf.h: the one way the library includes tinygltf (Debian libtinygltf-dev's tiny_gltf.h), with
// the one configuration every translation unit must share (the class layout depends on it; see
// tinygltf_impl.cpp, which compiles the implementation into the library):
//   TINYGLTF_NO_STB_IMAGE        the reader installs its own image loader (keeps the encoded bytes)
//   TINYGLTF_NO_STB_IMAGE_WRITE  images are never decoded or encoded, only moved
#pragma once

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>
