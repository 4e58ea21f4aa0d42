// The scheduler behind `fluence farm`: the four things the farm asks of one, so that another
// (Grid Engine, Deadline, OpenCue, ...) is one more class.
//
// Conventions:
// - A job array runs one command per task index: the array's command followed by the index as its
//   last argument. Indices are the plan's task indices (0-based), so a resubmission names only the
//   tasks it redoes.
// - Logs: `logPattern` is a path in which "%a" stands for the task index (Slurm's own filename
//   pattern); every backend appends to it, so the log of a task keeps all its attempts.
// - A dependent job runs only when every job of `afterOk` ended with all its tasks successful, and
//   after every job of `afterAny` ended whatever the result; when an `afterOk` job failed, it is
//   dropped (never runs) rather than left waiting.
// - Job ids are strings the backend chooses; the plan file records them so that `fluence farm
//   status` can poll them later, from another process.
// - Errors from the scheduler (not installed, refused the job, unreachable) throw SchedulerError
//   with the scheduler's own message.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace fluence::app {

class SchedulerError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct ArrayJob {
    std::string name;                  // shown by the scheduler
    std::vector<std::string> command;  // argv; each task appends its index
    std::vector<int> indices;          // the tasks to run
    int maxParallel = 0;               // at most this many tasks at once (0: the scheduler's choice)
    int cpusPerTask = 0;               // CPUs to reserve per task (0: the scheduler's default)
    std::string logPattern;            // "%a": the task index
    std::string workDir;               // the tasks' working directory
};

struct SingleJob {
    std::string name;
    std::vector<std::string> command;  // argv
    std::string logPath;
    std::string workDir;
};

struct Dependencies {
    std::vector<std::string> afterOk, afterAny;  // job ids
};

enum class QueueState { Pending, Running };

// A task (or a single job, index -1) the scheduler still holds.
struct QueuedTask {
    std::string jobId;
    int index = -1;
    QueueState state = QueueState::Pending;
};

class FarmBackend {
public:
    virtual ~FarmBackend() = default;
    virtual std::string name() const = 0;
    // Submits one task per index of `job`; returns the job id.
    virtual std::string submitArray(const ArrayJob& job) = 0;
    // Submits `job` to run after `dependencies` (see above); returns its job id.
    virtual std::string submitDependent(const SingleJob& job, const Dependencies& dependencies) = 0;
    // The tasks of `jobIds` that are still pending or running; finished ones are not listed.
    virtual std::vector<QueuedTask> poll(const std::vector<std::string>& jobIds) = 0;
    // Removes the jobs from the queue, stopping the tasks that run.
    virtual void cancel(const std::vector<std::string>& jobIds) = 0;
};

// The backend named `name` ("slurm" or "local"); `maxLocalJobs` is the local backend's task limit.
// Throws std::invalid_argument for another name.
std::unique_ptr<FarmBackend> makeFarmBackend(const std::string& name, int maxLocalJobs);
// "slurm, local", for messages.
std::string farmBackendNames();

}  // namespace fluence::app
