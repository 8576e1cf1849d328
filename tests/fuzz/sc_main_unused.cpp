// libsystemc.so (Debian's SystemC 2.3.4) defines main() and refers to
// sc_main, so every binary linked against it must define sc_main. The fuzz
// and replay binaries have their own main (libFuzzer's, or replay_main.cpp's,
// which the linker prefers to the library's) and use SystemC only for its
// integer types: their sc_main is never called.
#include <cstdio>

extern "C" int sc_main(int, char**) {
  std::fprintf(stderr, "sc_main: not used by this binary\n");
  return 2;
}
