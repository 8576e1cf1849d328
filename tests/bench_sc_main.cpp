// libsystemc supplies a main() that calls sc_main; ours replaces it only to
// silence the SystemC banner, then runs Google Benchmark from sc_main.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <systemc>

extern "C" int sc_main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

int main(int argc, char** argv) {
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  return sc_core::sc_elab_and_sim(argc, argv);
}
