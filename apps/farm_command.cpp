#include "apps/farm_command.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include <unistd.h>

#include "apps/cli_options.h"
#include "apps/farm_backend.h"
#include "apps/farm_plan.h"
#include "apps/farm_process.h"
#include "apps/farm_task.h"
#include "apps/json.h"
#include "apps/scene_loading.h"
#include "output/atomic_file.h"
#include "output/tile_assembly.h"

namespace fs = std::filesystem;

namespace fluence::app {

namespace {

struct SubmitOptions {
    std::string scene, folder, backend;
    std::vector<double> frames;  // empty: the stage's default frame
    int columns = 1, rows = 1;
    int jobs = 0, threads = 0;
    std::vector<std::string> renderArgs;
};

int parseCount(const std::string& flag, const std::string& text, int least) {
    int v = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (error != std::errc() || end != text.data() + text.size() || v < least)
        throw UsageError(flag + " expects a whole number of at least " + std::to_string(least) + ", got '" + text +
                         "'");
    return v;
}

bool inPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    if (!path) return false;
    for (std::string_view rest(path); !rest.empty();) {
        const std::size_t colon = rest.find(':');
        const fs::path dir(std::string(rest.substr(0, colon)));
        if (!dir.empty() && ::access((dir / program).c_str(), X_OK) == 0) return true;
        rest = colon == std::string_view::npos ? std::string_view() : rest.substr(colon + 1);
    }
    return false;
}

// Whether a Slurm controller answers: sbatch is installed and `sinfo` reaches a cluster (installed
// Slurm without a running cluster means the local backend).
bool slurmAnswers() {
    if (!inPath("sbatch") || !inPath("sinfo")) return false;
    try {
        return runCommand({"sinfo", "-h", "-o", "%T"}).exitCode == 0;
    } catch (const SpawnError&) {
        return false;
    }
}

// The render arguments the farm sets per task cannot be given after `--`.
void checkRenderArgs(const SubmitOptions& o) {
    std::vector<std::string> args = {o.scene};
    args.insert(args.end(), o.renderArgs.begin(), o.renderArgs.end());
    const RenderOptions r = parseRenderOptions(args);  // throws UsageError for what render refuses
    const RenderOptions defaults;
    const char* taken =
        !r.output.empty() ? "-o/--output (the farm names each task's output)"
        : r.frame || r.frameCount != 1 || r.frameIncrement != defaults.frameIncrement ? "-f/-n/-i (use --frames)"
        : r.tileCount || r.tileSuffix != defaults.tileSuffix ? "--tile-count/--tile-suffix (use --tiles)"
        : r.threads != 0                                     ? "-j/--threads (give it before --)"
        : !r.summary.empty()                                 ? "--summary (each task records its own result)"
        : !r.preview.empty()                                 ? "--preview (the farm writes EXR images only)"
                                                             : nullptr;
    if (taken) throw UsageError(std::string("the render arguments after -- cannot hold ") + taken);
}

SubmitOptions parseSubmit(const std::vector<std::string>& args) {
    SubmitOptions o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw UsageError(arg + " needs a value");
            return args[++i];
        };
        if (arg == "--") {
            o.renderArgs.assign(args.begin() + std::ptrdiff_t(i) + 1, args.end());
            break;
        } else if (arg == "--frames") {
            o.frames = parseFrameRange(value());
        } else if (arg == "--tiles") {
            o.columns = parseCount(arg, value(), 1);
            o.rows = parseCount(arg, value(), 1);
            if (o.columns > 1024 || o.rows > 1024) throw UsageError("--tiles needs X and Y from 1 to 1024");
        } else if (arg == "--backend") {
            o.backend = value();
            if (o.backend != "slurm" && o.backend != "local")
                throw UsageError("--backend must be one of " + farmBackendNames() + ", got '" + o.backend + "'");
        } else if (arg == "--output-dir") {
            o.folder = value();
        } else if (arg == "--jobs") {
            o.jobs = parseCount(arg, value(), 1);
        } else if (arg == "-j" || arg == "--threads") {
            o.threads = parseCount(arg, value(), 0);
        } else if (arg.starts_with("-")) {
            throw UsageError("unknown option '" + arg + "' for farm submit (render options go after --)");
        } else if (o.scene.empty()) {
            o.scene = arg;
        } else {
            throw UsageError("unexpected argument '" + arg + "' (the scene is already " + o.scene + ")");
        }
    }
    if (o.scene.empty()) throw UsageError("farm submit needs a scene");
    if (o.folder.empty()) o.folder = fs::path(o.scene).stem().string() + "_farm";
    if (o.backend.empty()) o.backend = slurmAnswers() ? "slurm" : "local";
    checkRenderArgs(o);
    return o;
}

// The folder argument of status, resume and merge.
std::string folderArgument(const std::string& action, const std::vector<std::string>& args) {
    if (args.size() != 1 || args[0].starts_with("-"))
        throw UsageError("farm " + action + " needs the farm's output folder, and only it");
    return args[0];
}

enum class TaskStatus { Done, Queued, Running, Failed, Missing };

const char* statusName(TaskStatus s) {
    switch (s) {
        case TaskStatus::Done: return "done";
        case TaskStatus::Queued: return "queued";
        case TaskStatus::Running: return "running";
        case TaskStatus::Failed: return "failed";
        case TaskStatus::Missing: return "missing";
    }
    return "?";
}

struct FarmState {
    std::vector<TaskStatus> tasks;
    std::vector<std::optional<TaskRecord>> records;
    std::vector<bool> imageDone;
    std::vector<std::string> queuedMergeJobs;
    std::vector<std::string> busyTaskJobs;  // task arrays that still hold queued or running tasks
    std::string schedulerNote;              // why the scheduler was not asked, if it was not
};

// Reads the output folder and asks the scheduler about the recorded jobs. When the scheduler
// cannot be asked: throws SchedulerError if `needScheduler`, else notes it and goes by the files.
FarmState inspectFarm(const FarmPlan& plan, FarmBackend& backend, bool needScheduler) {
    std::vector<std::string> jobIds;
    for (const FarmSubmission& s : plan.submissions)
        if (s.backend == backend.name())
            for (const std::string& id : {s.taskJob, s.mergeJob})
                if (!id.empty()) jobIds.push_back(id);
    std::vector<QueuedTask> queued;
    FarmState state;
    try {
        queued = backend.poll(jobIds);
    } catch (const SchedulerError& e) {
        if (needScheduler) throw;
        state.schedulerNote = e.what();
    }
    for (const FarmTask& task : plan.tasks) {
        std::optional<TaskRecord> record = readTaskRecord(plan, task.index);
        TaskStatus status = record ? TaskStatus::Failed : TaskStatus::Missing;
        if (record && record->exitCode == 0) status = TaskStatus::Missing;  // its output was removed since
        for (const FarmSubmission& s : plan.submissions)
            for (const QueuedTask& q : queued)
                if (q.jobId == s.taskJob && q.index == task.index && s.backend == backend.name()) {
                    status = q.state == QueueState::Running ? TaskStatus::Running : TaskStatus::Queued;
                    if (std::find(state.busyTaskJobs.begin(), state.busyTaskJobs.end(), q.jobId) ==
                        state.busyTaskJobs.end())
                        state.busyTaskJobs.push_back(q.jobId);
                }
        if (fs::exists(plan.path(task.output))) status = TaskStatus::Done;
        state.tasks.push_back(status);
        state.records.push_back(record);
    }
    for (const FarmImage& image : plan.images) state.imageDone.push_back(fs::exists(plan.path(image.output)));
    for (const FarmSubmission& s : plan.submissions)
        for (const QueuedTask& q : queued)
            if (q.jobId == s.mergeJob && s.backend == backend.name()) state.queuedMergeJobs.push_back(q.jobId);
    return state;
}

bool allImagesDone(const FarmState& state) {
    return std::all_of(state.imageDone.begin(), state.imageDone.end(), [](bool done) { return done; });
}

// Prints the state; returns 0 (all done), kExitFarmPending or kExitFarmIncomplete.
int reportState(const FarmPlan& plan, const FarmState& state) {
    std::printf("fluence farm: %s: %zu tasks (%zu %s, %dx%d tiles), backend %s\n", plan.folder.c_str(),
                plan.tasks.size(), plan.images.size(), plan.images.size() == 1 ? "image" : "images", plan.tileColumns,
                plan.tileRows, plan.backend.c_str());
    if (!state.schedulerNote.empty())
        std::printf("  (the scheduler was not asked, so queued and running tasks show as failed or missing: %s)\n",
                    state.schedulerNote.c_str());
    int counts[5] = {};
    for (const FarmTask& task : plan.tasks) {
        const TaskStatus s = state.tasks[task.index];
        ++counts[int(s)];
        std::string detail = task.output;
        if (s == TaskStatus::Failed) {
            const TaskRecord& r = *state.records[task.index];
            detail = (r.exitCode ? "exit " + std::to_string(*r.exitCode)
                                 : std::string("ended without recording an exit (killed?)")) +
                     " on attempt " + std::to_string(r.attempts) + "; log logs/task_" + std::to_string(task.index) +
                     ".log";
        }
        std::printf("  task %-4d %s%s tile %-3d %-8s %s\n", task.index, task.frame ? "frame " : "",
                    task.frame ? jsonNumber(*task.frame).c_str() : "", task.tile, statusName(s), detail.c_str());
    }
    std::size_t imagesDone = 0;
    for (std::size_t i = 0; i < plan.images.size(); ++i) {
        imagesDone += state.imageDone[i];
        std::printf("  image %-40s %s\n", plan.images[i].output.c_str(), state.imageDone[i] ? "done" : "not done");
    }
    for (const std::string& id : state.queuedMergeJobs) std::printf("  merge job %s is queued\n", id.c_str());
    std::printf("summary: %d done, %d queued, %d running, %d failed, %d missing; %zu of %zu images done\n", counts[0],
                counts[1], counts[2], counts[3], counts[4], imagesDone, plan.images.size());
    if (imagesDone == plan.images.size()) return kExitOk;
    if (counts[1] + counts[2] > 0 || !state.queuedMergeJobs.empty()) return kExitFarmPending;
    std::printf("run `fluence farm resume %s` to redo the failed and missing tasks\n", plan.folder.c_str());
    return kExitFarmIncomplete;
}

// Submits `indices` as a task array and the merge job after it (and after `afterAny`), records
// the submission in the plan. Throws SchedulerError; then nothing stays queued.
void submitTasks(FarmPlan& plan, FarmBackend& backend, const std::vector<int>& indices,
                 const std::vector<std::string>& afterAny) {
    for (const char* folder : {"logs", "tasks"}) fs::create_directories(plan.path(folder));
    const std::string fluence = currentExecutable(), name = "fluence-" + fs::path(plan.scene).stem().string();
    FarmSubmission submission;
    submission.backend = backend.name();
    submission.tasks = indices;
    if (!indices.empty()) {
        ArrayJob array;
        array.name = name;
        array.command = {fluence, "farm", "task", plan.folder};
        array.indices = indices;
        array.maxParallel = plan.maxParallel;
        array.cpusPerTask = plan.threadsPerTask;
        array.logPattern = plan.path("logs/task_%a.log");
        array.workDir = plan.folder;
        submission.taskJob = backend.submitArray(array);
    }
    SingleJob merge;
    merge.name = name + "-merge";
    merge.command = {fluence, "farm", "merge", plan.folder};
    merge.logPath = plan.path("logs/merge.log");
    merge.workDir = plan.folder;
    Dependencies after;
    if (!submission.taskJob.empty()) after.afterOk.push_back(submission.taskJob);
    after.afterAny = afterAny;
    try {
        submission.mergeJob = backend.submitDependent(merge, after);
    } catch (const SchedulerError&) {
        if (!submission.taskJob.empty()) backend.cancel({submission.taskJob});
        throw;
    }
    plan.submissions.push_back(submission);
    writeFarmPlan(plan);
    if (backend.name() != "local")
        std::printf(
            "fluence farm: submitted %zu tasks as %s job %s and the merge as job %s; `fluence farm status %s` follows "
            "them\n",
            indices.size(), backend.name().c_str(), submission.taskJob.empty() ? "(none)" : submission.taskJob.c_str(),
            submission.mergeJob.c_str(), plan.folder.c_str());
}

// After a submission: the local backend has done the work, so its state is the result; a
// scheduler's jobs are on their way.
int afterSubmission(const FarmPlan& plan, FarmBackend& backend) {
    if (backend.name() != "local") return kExitOk;
    return reportState(plan, inspectFarm(plan, backend, false));
}

int runSubmit(const std::vector<std::string>& args) {
    const SubmitOptions o = parseSubmit(args);
    if (!fs::is_regular_file(o.scene)) {
        printError("cannot open the scene " + o.scene + ": no such file");
        return kExitMissingInput;
    }
    FarmPlan plan;
    plan.folder = fs::absolute(o.folder).lexically_normal().string();
    while (plan.folder.size() > 1 && plan.folder.back() == '/') plan.folder.pop_back();
    if (fs::exists(plan.path(kFarmPlanFile))) {
        printError(plan.path(kFarmPlanFile) +
                   " exists: that folder holds a farm render already (`fluence farm resume " + o.folder +
                   "`, or give another --output-dir)");
        return kExitUsage;
    }
    plan.scene = fs::absolute(o.scene).lexically_normal().string();
    plan.renderArgs = o.renderArgs;
    plan.tileColumns = o.columns;
    plan.tileRows = o.rows;
    plan.backend = o.backend;
    plan.maxParallel = o.jobs;
    plan.threadsPerTask = o.threads;
    const int cores = std::max(1, int(std::thread::hardware_concurrency()));
    if (o.backend == "local" && o.threads == 0)
        plan.threadsPerTask = std::max(1, cores / (o.jobs > 0 ? std::min(o.jobs, cores) : cores));
    planTasks(plan, o.frames);
    std::unique_ptr<FarmBackend> backend = makeFarmBackend(plan.backend, plan.maxParallel);
    std::vector<int> all(plan.tasks.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = int(i);
    try {
        fs::create_directories(plan.folder);
        writeFarmPlan(plan);  // before any task starts: the tasks read it
    } catch (const std::exception& e) {
        printError("cannot write the farm plan in " + plan.folder + ": " + e.what());
        return kExitOutput;
    }
    try {
        submitTasks(plan, *backend, all, {});
    } catch (const SchedulerError& e) {
        printError(e.what());
        return kExitFarmScheduler;
    }
    return afterSubmission(plan, *backend);
}

int runStatus(const std::string& folder) {
    const FarmPlan plan = readFarmPlan(folder);
    std::unique_ptr<FarmBackend> backend = makeFarmBackend(plan.backend, plan.maxParallel);
    return reportState(plan, inspectFarm(plan, *backend, false));
}

int runResume(const std::string& folder) {
    FarmPlan plan = readFarmPlan(folder);
    std::unique_ptr<FarmBackend> backend = makeFarmBackend(plan.backend, plan.maxParallel);
    FarmState state;
    try {
        state = inspectFarm(plan, *backend, true);  // never resubmit a task the scheduler still runs
        std::vector<int> redo;
        for (const FarmTask& task : plan.tasks)
            if (state.tasks[task.index] == TaskStatus::Failed || state.tasks[task.index] == TaskStatus::Missing)
                redo.push_back(task.index);
        if (allImagesDone(state)) {
            std::printf("fluence farm: %s: every image is done; nothing to resume\n", plan.folder.c_str());
            return kExitOk;
        }
        if (redo.empty() && !state.queuedMergeJobs.empty()) {
            std::printf("fluence farm: %s: nothing failed; the tasks and the merge are still queued or running\n",
                        plan.folder.c_str());
            return kExitFarmPending;
        }
        std::printf("fluence farm: %s: resubmitting %zu task%s and the merge\n", plan.folder.c_str(), redo.size(),
                    redo.size() == 1 ? "" : "s");
        submitTasks(plan, *backend, redo, state.busyTaskJobs);
    } catch (const SchedulerError& e) {
        printError(e.what());
        return kExitFarmScheduler;
    }
    return afterSubmission(plan, *backend);
}

int runMerge(const std::string& folder) {
    const FarmPlan plan = readFarmPlan(folder);
    int result = kExitOk;
    for (const FarmImage& image : plan.images) {
        const std::string out = plan.path(image.output);
        if (fs::exists(out)) continue;
        std::vector<std::string> tiles, missing;
        for (int index : image.tasks)
            (fs::exists(plan.path(plan.tasks[index].output)) ? tiles : missing).push_back(plan.tasks[index].output);
        if (!missing.empty()) {
            printError(image.output + " cannot be merged yet: " + std::to_string(missing.size()) +
                       " tasks are not done (" + missing[0] + (missing.size() > 1 ? ", ..." : "") + ")");
            result = result == kExitOk ? kExitFarmIncomplete : result;
            continue;
        }
        for (std::string& tile : tiles) tile = plan.path(tile);
        try {
            output::assembleTiles(tiles, out);
            std::printf("fluence farm: merged %zu tiles into %s\n", tiles.size(), out.c_str());
        } catch (const output::TileReadError& e) {
            printError(e.what());
            result = result == kExitOk ? kExitMissingInput : result;
        } catch (const output::TileMismatchError& e) {
            printError(e.what());
            result = result == kExitOk ? kExitScene : result;
        } catch (const output::OutputError& e) {
            printError(e.what());
            result = result == kExitOk ? kExitOutput : result;
        }
    }
    return result;
}

}  // namespace

int runFarm(const std::vector<std::string>& args) {
    if (args.empty()) throw UsageError("farm needs an action: submit, status, resume, merge or task");
    const std::string action = args[0];
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    try {
        if (action == "submit") return runSubmit(rest);
        if (action == "status") return runStatus(folderArgument(action, rest));
        if (action == "resume") return runResume(folderArgument(action, rest));
        if (action == "merge") return runMerge(folderArgument(action, rest));
        if (action == "task") {
            if (rest.size() != 2) throw UsageError("farm task needs the farm's output folder and a task index");
            return runFarmTask(rest[0], parseCount("farm task", rest[1], 0));
        }
    } catch (const FarmPlanError& e) {
        printError(e.what());
        return kExitMissingInput;
    } catch (const fs::filesystem_error& e) {
        printError(e.what());
        return kExitOutput;
    } catch (const output::OutputError& e) {
        printError(e.what());
        return kExitOutput;
    }
    throw UsageError("unknown farm action '" + action + "' (submit, status, resume, merge or task)");
}

}  // namespace fluence::app
