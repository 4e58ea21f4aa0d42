#include "apps/farm_slurm_backend.h"

#include <algorithm>
#include <charconv>
#include <sstream>

#include "apps/farm_process.h"

namespace fluence::app {

namespace {

// Runs a Slurm command; returns its standard output. Throws SchedulerError with Slurm's message.
std::string slurm(const std::vector<std::string>& argv) {
    CommandOutput r;
    try {
        r = runCommand(argv);
    } catch (const SpawnError& e) {
        throw SchedulerError(std::string(e.what()) + " (is Slurm installed and in PATH?)");
    }
    if (r.exitCode != 0) {
        std::string message = r.err.empty() ? r.out : r.err;
        while (!message.empty() && message.back() == '\n') message.pop_back();
        throw SchedulerError(argv[0] + " failed (exit " + std::to_string(r.exitCode) + "): " + message);
    }
    return r.out;
}

std::string joined(const std::vector<std::string>& items, char separator) {
    std::string out;
    for (const std::string& item : items) {
        if (!out.empty()) out += separator;
        out += item;
    }
    return out;
}

// "--parsable" prints "JOBID" or "JOBID;CLUSTER".
std::string parsedJobId(const std::string& out) {
    std::string id = out.substr(0, out.find_first_of(";\n"));
    if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
        throw SchedulerError("sbatch printed no job id: '" + out + "'");
    return id;
}

std::vector<std::string> sbatchCommon(const std::string& name, const std::string& log, const std::string& workDir) {
    return {"sbatch", "--parsable", "--job-name=" + name, "--output=" + log, "--open-mode=append", "--chdir=" + workDir};
}

// Slurm's --array list: runs of consecutive indices as ranges, "0-3,7,9-10".
std::string arrayIndices(std::vector<int> indices) {
    std::sort(indices.begin(), indices.end());
    std::vector<std::string> runs;
    for (std::size_t i = 0; i < indices.size();) {
        std::size_t j = i;
        while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1) ++j;
        std::string run = std::to_string(indices[i]);
        if (j > i) run.append("-").append(std::to_string(indices[j]));
        runs.push_back(run);
        i = j + 1;
    }
    return joined(runs, ',');
}

}  // namespace

std::string SlurmFarmBackend::submitArray(const ArrayJob& job) {
    std::string indices = arrayIndices(job.indices);
    if (job.maxParallel > 0) indices.append("%").append(std::to_string(job.maxParallel));
    std::vector<std::string> argv = sbatchCommon(job.name, job.logPattern, job.workDir);
    argv.push_back("--array=" + indices);
    if (job.cpusPerTask > 0) argv.push_back("--cpus-per-task=" + std::to_string(job.cpusPerTask));
    argv.push_back("--wrap=" + shellCommand(job.command) + " \"$SLURM_ARRAY_TASK_ID\"");
    return parsedJobId(slurm(argv));
}

std::string SlurmFarmBackend::submitDependent(const SingleJob& job, const Dependencies& dependencies) {
    std::vector<std::string> argv = sbatchCommon(job.name, job.logPath, job.workDir);
    std::vector<std::string> conditions;
    if (!dependencies.afterOk.empty()) conditions.push_back("afterok:" + joined(dependencies.afterOk, ':'));
    if (!dependencies.afterAny.empty()) conditions.push_back("afterany:" + joined(dependencies.afterAny, ':'));
    if (!conditions.empty()) {
        argv.push_back("--dependency=" + joined(conditions, ','));
        argv.push_back("--kill-on-invalid-dep=yes");
    }
    argv.push_back("--wrap=" + shellCommand(job.command));
    return parsedJobId(slurm(argv));
}

std::vector<QueuedTask> SlurmFarmBackend::poll(const std::vector<std::string>& jobIds) {
    if (jobIds.empty()) return {};
    CommandOutput r;
    try {
        r = runCommand({"squeue", "-h", "-r", "-j", joined(jobIds, ','), "-o", "%F %K %T"});
    } catch (const SpawnError& e) {
        throw SchedulerError(std::string(e.what()) + " (is Slurm installed and in PATH?)");
    }
    // Jobs the controller has forgotten (MinJobAge after they ended) make squeue fail so.
    if (r.exitCode != 0 && r.err.find("Invalid job id") != std::string::npos) return {};
    if (r.exitCode != 0) throw SchedulerError("squeue failed (exit " + std::to_string(r.exitCode) + "): " + r.err);
    std::vector<QueuedTask> tasks;
    std::istringstream lines(r.out);
    for (std::string jobId, index, state; lines >> jobId >> index >> state;) {
        QueuedTask& t = tasks.emplace_back();
        t.jobId = jobId;
        std::from_chars(index.data(), index.data() + index.size(), t.index);  // "N/A" for a single job: stays -1
        t.state = state == "RUNNING" || state == "COMPLETING" || state == "CONFIGURING" ? QueueState::Running
                                                                                        : QueueState::Pending;
    }
    return tasks;
}

void SlurmFarmBackend::cancel(const std::vector<std::string>& jobIds) {
    if (jobIds.empty()) return;
    std::vector<std::string> argv = {"scancel"};
    argv.insert(argv.end(), jobIds.begin(), jobIds.end());
    slurm(argv);
}

}  // namespace fluence::app
