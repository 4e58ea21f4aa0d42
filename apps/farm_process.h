// Child processes for `fluence farm`: scheduler commands (sbatch, squeue, scancel) with their
// output captured, and render tasks with their output appended to a log. Every command is an argv
// vector started with posix_spawnp (no shell, so no argument is ever re-parsed); the one place a
// shell reads our text, a Slurm job script, quotes each argument with shellQuoted().
#pragma once

#include <sys/types.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace fluence::app {

// A command that could not be started (not installed, not executable).
class SpawnError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct CommandOutput {
    int exitCode = -1;  // the exit status; 128 + N when killed by signal N
    std::string out, err;
};

// Runs `argv` (argv[0] looked up in PATH) with no standard input and waits for it; captures its
// standard output and error. Throws SpawnError when it cannot be started.
CommandOutput runCommand(const std::vector<std::string>& argv);

// Starts `argv` in the folder `workDir` ("": this one) with no standard input and its standard
// output and error appended to `logPath` (created if needed). Returns its process id. Throws
// SpawnError.
pid_t startLogged(const std::vector<std::string>& argv, const std::string& logPath, const std::string& workDir);

// Waits for the child `pid`; returns its exit status (128 + N when killed by signal N).
int waitForExit(pid_t pid);
// Waits for whichever child ends first; returns its id and sets `exitCode` as waitForExit does.
pid_t waitForAny(int& exitCode);

// `text` quoted for a POSIX shell: 'it'\''s' style, so it reads back as exactly one word.
std::string shellQuoted(const std::string& text);
// The words quoted and joined by spaces: a command a user can paste into a shell.
std::string shellCommand(const std::vector<std::string>& argv);

// The absolute path of the running executable (/proc/self/exe).
std::string currentExecutable();

}  // namespace fluence::app
