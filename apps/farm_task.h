// One task of a farm plan, as a scheduler runs it: `fluence farm task FOLDER INDEX` renders the
// task's tile of its frame (`fluence render` in this process, with the plan's render arguments)
// and records the attempt in FOLDER/tasks/task_INDEX.json:
//   {"task": 2, "attempts": 1, "exitCode": 0}   (exitCode null while the attempt runs, or when
//                                                 it was killed before it could record one)
// The render's output is written atomically, so the task is done exactly when that file exists;
// the record only tells a failed task (non-zero exit, or none recorded) from one never run.
//
// Threads: SLURM_CPUS_PER_TASK when the scheduler sets it, else the plan's threadsPerTask (0:
// every core).
//
// Test hook: with FLUENCE_FARM_FAIL_TASK=N in the environment, task N fails on its first attempt
// (exit 1, before rendering, with a message naming the variable) and renders normally on the
// next, so a test can exercise `fluence farm status` and `resume` on a real failure.
#pragma once

#include <optional>
#include <string>

#include "apps/farm_plan.h"

namespace fluence::app {

inline constexpr const char* kFarmFailTaskVariable = "FLUENCE_FARM_FAIL_TASK";

struct TaskRecord {
    int attempts = 0;
    std::optional<int> exitCode;  // none: the last attempt has not recorded an end
};

// FOLDER/tasks/task_INDEX.json
std::string taskRecordPath(const FarmPlan& plan, int index);
// The task's record, or none when it never ran (or the record is unreadable).
std::optional<TaskRecord> readTaskRecord(const FarmPlan& plan, int index);

// Runs task `index` of the plan in `folder`; returns the exit code (the render's, or those of
// apps/scene_loading.h for a plan that cannot be read or a record that cannot be written).
int runFarmTask(const std::string& folder, int index);

}  // namespace fluence::app
