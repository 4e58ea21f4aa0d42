// The `fluence` command line as a function: the arguments after the program name in, the exit
// code out (apps/scene_loading.h lists the codes). main() is this; bench/render_census.cpp calls
// it once per file in a forked child, to run the CLI over thousands of files without starting a
// process each time.
#pragma once

#include <string>
#include <vector>

namespace fluence::app {

int runCommandLine(std::vector<std::string> args);

}  // namespace fluence::app
