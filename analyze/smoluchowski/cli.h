// The command line of coolgas-smoluchowski (CLI11): options, --help text with
// units and the time convention, and the dispatch to a run or the accuracy study.
#pragma once
#include <iosfwd>

namespace coolgas::smoluchowski {

// Parses argv and runs; returns the exit code. Bad options throw InputError.
int smoluchowski_main(int argc, char** argv, std::ostream& out, std::ostream& err);

}  // namespace coolgas::smoluchowski
