// `fluence farm`: a render split into tasks (one per frame and tile), run by a scheduler
// (apps/farm_backend.h), merged, checked and resumed from the plan file in its output folder
// (apps/farm_plan.h).
//
//   fluence farm submit SCENE [--frames A-B[xK]] [--tiles X Y] [--backend slurm|local]
//                             [--output-dir DIR] [--jobs N] [-j N] [-- RENDER ARGS...]
//   fluence farm status DIR     done / queued / running / failed / missing per task and image
//   fluence farm resume DIR     resubmits the failed and missing tasks, and the merge
//   fluence farm merge DIR      assembles each image whose tiles are all done (the merge job)
//   fluence farm task DIR N     runs task N (what the scheduler runs; apps/farm_task.h)
//
// Exit codes, beyond those of `fluence render` (apps/scene_loading.h):
//   0 every image is done (status; submit and resume with the local backend), or the jobs were
//     submitted (submit and resume with a scheduler)
//   8 work is still queued or running    9 work is missing or failed: run `fluence farm resume`
//   10 the scheduler could not be run or refused the job (its message is printed)
#pragma once

#include <string>
#include <vector>

namespace fluence::app {

inline constexpr int kExitFarmPending = 8;
inline constexpr int kExitFarmIncomplete = 9;
inline constexpr int kExitFarmScheduler = 10;

// Runs `fluence farm ARGS...` (the arguments after "farm"); returns the exit code. Throws
// UsageError for arguments it cannot parse.
int runFarm(const std::vector<std::string>& args);

}  // namespace fluence::app
