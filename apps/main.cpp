// The `fluence` command line (apps/command_line.h).
#include <string>
#include <vector>

#include "apps/command_line.h"

int main(int argc, char** argv) {
    return fluence::app::runCommandLine(std::vector<std::string>(argv + 1, argv + argc));
}
