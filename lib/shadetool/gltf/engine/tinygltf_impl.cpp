// tinygltf_impl.cpp: tinygltf's implementation (Debian libtinygltf-dev's header, tiny_gltf.h 2.7.0)
// compiled into the library, instead of linking Debian's libtinygltf.so.
//
// Why: a process may hold another copy of tinygltf (Open3D's Python module has one). With the shared
// library, our calls went through the dynamic linker and could bind to that other copy, built with
// other options: `import open3d` before `import shadetool` made every glTF read fail with "FS
// callback[s] not set" (issue 28, item 7). Compiled here, tinygltf's symbols are hidden like the rest
// of the library (CXX_VISIBILITY_PRESET hidden) and bind inside it.
// Images: the reader installs its own loader (gltf_read.cpp keeps the encoded bytes) and the writer
// never decodes or encodes one, so stb_image and stb_image_write are left out (engine/tinygltf.h).
#define TINYGLTF_IMPLEMENTATION
#include <shadetool/gltf/engine/tinygltf.h>
