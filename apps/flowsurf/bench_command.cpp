#include "commands.h"

int flowsurfBenchPlaceholder();

namespace flowsurf::app {
int runBench(const BenchOptions&) { return 0; }
}  // namespace flowsurf::app
