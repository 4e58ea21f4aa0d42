// The `slurm` farm backend: a job array through `sbatch --parsable --array=...`, the dependent job
// through `--dependency=afterok:...,afterany:... --kill-on-invalid-dep=yes`, polling through
// `squeue -h -r -j IDS` and cancelling through `scancel`. The commands are found in PATH and
// talk to the cluster of SLURM_CONF (or the default configuration), and the submitting
// environment goes with the job (sbatch's default --export=ALL).
//
// Each job is given to sbatch as `--wrap` text: the command's arguments single-quoted for
// /bin/sh, and for an array the task index appended as "$SLURM_ARRAY_TASK_ID". Logs use Slurm's
// filename patterns ("%a": the task index) and are opened in append mode. A task array of more
// than the cluster's MaxArraySize (1001 by default) tasks is refused by sbatch, and its message
// is passed on.
#pragma once

#include "apps/farm_backend.h"

namespace fluence::app {

class SlurmFarmBackend : public FarmBackend {
public:
    std::string name() const override { return "slurm"; }
    std::string submitArray(const ArrayJob& job) override;
    std::string submitDependent(const SingleJob& job, const Dependencies& dependencies) override;
    std::vector<QueuedTask> poll(const std::vector<std::string>& jobIds) override;
    void cancel(const std::vector<std::string>& jobIds) override;
};

}  // namespace fluence::app
