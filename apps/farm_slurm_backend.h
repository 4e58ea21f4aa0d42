// The `slurm` farm backend: a job array through `sbatch --parsable --array=...`, the dependent job
// through `--dependency=afterok:...,afterany:... --kill-on-invalid-dep=yes`, polling through
// `squeue -h -r -j IDS` and cancelling through `scancel`. The commands are found in PATH and
// talk to the cluster of SLURM_CONF (or the default configuration), and the submitting
// environment goes with the job (sbatch's default --export=ALL).
//
// Each job is given to sbatch as `--wrap` text: the command's arguments single-quoted for
// /bin/sh, and for an array the task index appended as "$SLURM_ARRAY_TASK_ID". Logs use Slurm's
// filename patterns ("%a": the task index) and are opened in append mode.
//
// Slurm refuses array indices at or above the cluster's MaxArraySize (`scontrol show config`;
// 1001 by default). A task array that reaches it is submitted as several arrays, the k-th holding
// tasks k * MaxArraySize on, shifted down to start at 0: its command adds the offset back
// ("$((SLURM_ARRAY_TASK_ID + OFFSET))") and redirects each task's output into the log its own
// index names. The job id recorded for such a task array is its arrays' ids joined by ':', each
// with "+OFFSET" after it when the offset is not 0 ("812:813+1001"); poll() reports their tasks by
// the plan's indices under that id, and the dependency, squeue and scancel calls take the plain
// ids. A --max-parallel limit applies to each array.
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
