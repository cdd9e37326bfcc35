// tinyobjloader's implementation compiled into the OBJ fuzz target, with the fuzzer's coverage and
// sanitizer instrumentation. The Debian shared library is not instrumented: libFuzzer would get no
// coverage feedback inside it and ASan would not see its out-of-bounds accesses. The executable's
// definitions take precedence over the shared library's at link time.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
