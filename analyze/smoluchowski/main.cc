// coolgas-smoluchowski: mean-field N(m,t) from the Smoluchowski equation.
// All logic lives in the library of this folder (analyze/smoluchowski/).
#include <iostream>

#include "analyze/smoluchowski/cli.h"
#include "common/interrupt.h"
#include "common/tool_main.h"

int main(int argc, char** argv) {
  return coolgas::run_tool("coolgas-smoluchowski", [&] {
    coolgas::watch_interrupts();  // its loops stop at SIGINT/SIGTERM: exit code 3
    return coolgas::smoluchowski::smoluchowski_main(argc, argv, std::cout, std::cerr);
  });
}
