// libFuzzer target: the OFF, PLY (ASCII and binary) and OBJ readers of
// c2blend-cgal-curvature (validation/cgal/c2blend_mesh_soup.hpp) and the soup checks run
// after them. Every input goes through all three readers; each must either return a
// soup or throw Input_error with a message. Any other exception, crash or sanitizer
// report is a bug.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "c2blend_mesh_soup.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size);

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  if (size > 65536)
    return 0;
  const std::string text(reinterpret_cast<const char *>(data), size);
  static const char *const exts[3] = {"off", "ply", "obj"};
  for (const char *ext : exts) {
    Soup soup;
    soup.path = std::string("fuzz.") + ext;
    std::istringstream in(text, std::ios::in | std::ios::binary);
    try {
      read_mesh_stream(in, ext, soup);
      check_soup(soup);
    } catch (const Input_error &e) {
      if (!e.what()[0])
        __builtin_trap();
    } catch (const std::exception &) {
      // the tool reports these too (main's catch): out of memory and the like
    }
  }
  return 0;
}
