// The `local` farm backend: the tasks run as child processes of `fluence farm` on this machine, at
// most N at a time, for users without a farm (and as the scheduler-free test of the farm logic).
//
// A job runs inside the call that submits it: submitArray() returns when every task has ended,
// and submitDependent() runs its job at once when its afterOk jobs all succeeded, or drops it (as
// Slurm's --kill-on-invalid-dep does) when one failed. So poll() finds nothing queued once a
// submit call has returned, and cancel() has nothing left to stop. SIGINT or SIGTERM reaches the
// tasks through the terminal's process group: a render interrupted that way writes nothing.
#pragma once

#include <map>

#include "apps/farm_backend.h"

namespace fluence::app {

class LocalFarmBackend : public FarmBackend {
public:
    explicit LocalFarmBackend(int maxJobs);  // maxJobs < 1: one per core

    std::string name() const override { return "local"; }
    std::string submitArray(const ArrayJob& job) override;
    std::string submitDependent(const SingleJob& job, const Dependencies& dependencies) override;
    std::vector<QueuedTask> poll(const std::vector<std::string>& jobIds) override;
    void cancel(const std::vector<std::string>& jobIds) override;

private:
    std::string newJobId();

    int maxJobs_;
    int submitted_ = 0;
    std::map<std::string, bool> succeeded_;  // job id -> every task exited with 0
};

}  // namespace fluence::app
