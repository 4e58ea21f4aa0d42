// The plan of a `fluence farm` render: the source of truth for submit, status, resume and merge,
// stored as FOLDER/farm.json in the farm's output folder.
//
// One task per (frame, tile), numbered frame by frame, tiles row by row from the top left (the
// order of `fluence render --tile-index`). Each task renders one tile of one frame to its own
// EXR, written atomically, so a task is done exactly when its output file exists. Each image
// (frame) lists the tasks whose tiles make it; with a 1x1 split the task writes the image itself.
// Paths inside the plan are relative to its folder, so the folder can be moved or mounted
// elsewhere; the scene is absolute. The file also records every submission (backend, job ids,
// the tasks submitted) so that `status` can ask the scheduler about them later.
//
// farm.json:
//   { "fluenceFarmPlan": 1, "scene": "/abs/scene.usda", "renderArgs": ["--spp", "64"],
//     "tiles": [X, Y], "backend": "slurm", "threadsPerTask": 0, "maxParallel": 0,
//     "tasks": [{"index": 0, "frame": 1 (null: the stage's default), "tile": 0,
//                "output": "tiles/scene.0001_tile0.exr"}, ...],
//     "images": [{"frame": 1, "output": "scene.0001.exr", "tasks": [0, 1, 2, 3]}, ...],
//     "submissions": [{"backend": "slurm", "tasks": [0, 1, 2, 3], "taskJob": "123",
//                      "mergeJob": "124"}, ...] }
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fluence::app {

// A plan file that is missing or not a plan; the message names the file.
class FarmPlanError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

inline constexpr const char* kFarmPlanFile = "farm.json";

struct FarmTask {
    int index = 0;
    std::optional<double> frame;  // none: the stage's default (no --frame)
    int tile = 0;
    std::string output;  // relative to the plan's folder
};

struct FarmImage {
    std::optional<double> frame;
    std::string output;      // relative to the plan's folder
    std::vector<int> tasks;  // its tiles' tasks, by tile index
};

struct FarmSubmission {
    std::string backend;
    std::vector<int> tasks;  // the tasks submitted (may be none: a merge alone)
    std::string taskJob;     // the array's job id ("" when no task was submitted)
    std::string mergeJob;    // the dependent merge job's id
};

struct FarmPlan {
    std::string folder;                   // absolute; where farm.json lives (not stored in it)
    std::string scene;                    // absolute
    std::vector<std::string> renderArgs;  // extra `fluence render` arguments, the same for every task
    int tileColumns = 1, tileRows = 1;
    std::string backend;
    int threadsPerTask = 0;  // 0: SLURM_CPUS_PER_TASK when set, else every core
    int maxParallel = 0;     // tasks at once (0: the backend's default)
    std::vector<FarmTask> tasks;
    std::vector<FarmImage> images;
    std::vector<FarmSubmission> submissions;

    // `relative` (a path the plan holds) under the plan's folder.
    std::string path(const std::string& relative) const;
    bool tiled() const { return tileColumns * tileRows > 1; }
};

// Parses --frames: "A", "A-B" or "A-BxK" (integers, B >= A, step K >= 1). Throws UsageError.
std::vector<double> parseFrameRange(const std::string& text);

// The tasks and images of a render of `scene` (absolute) at `frames` (empty: the stage's
// default frame) split into columns x rows tiles. Images are named after the scene: NAME.exr, or
// NAME.0001.exr per frame; tiles go to tiles/NAME[.0001]_tileN.exr.
void planTasks(FarmPlan& plan, const std::vector<double>& frames);

// The `fluence render` arguments (after "render") of task `task`, with `threads` worker threads.
std::vector<std::string> taskRenderArgs(const FarmPlan& plan, const FarmTask& task, int threads);

// Writes FOLDER/farm.json atomically. Throws output::OutputError.
void writeFarmPlan(const FarmPlan& plan);
// Reads FOLDER/farm.json. Throws FarmPlanError naming the file.
FarmPlan readFarmPlan(const std::string& folder);

}  // namespace fluence::app
