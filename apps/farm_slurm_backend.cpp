#include "apps/farm_slurm_backend.h"

#include <algorithm>
#include <charconv>
#include <map>
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
    return {"sbatch",          "--parsable",         "--job-name=" + name,
            "--output=" + log, "--open-mode=append", "--chdir=" + workDir};
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

// The cluster's MaxArraySize (`scontrol show config`): an array's task indices must stay below it.
// Slurm's default, 1001, when it cannot be read.
int maxArraySize() {
    constexpr int kSlurmDefault = 1001;
    std::string config;
    try {
        config = slurm({"scontrol", "show", "config"});
    } catch (const SchedulerError&) {
        return kSlurmDefault;
    }
    std::istringstream lines(config);
    for (std::string line; std::getline(lines, line);) {
        if (!line.starts_with("MaxArraySize")) continue;
        const std::size_t equals = line.find('=');
        int value = 0;
        if (equals == std::string::npos) break;
        const std::size_t digits = line.find_first_of("0123456789", equals);
        if (digits != std::string::npos &&
            std::from_chars(line.data() + digits, line.data() + line.size(), value).ec == std::errc() && value > 0)
            return value;
        break;
    }
    return kSlurmDefault;
}

// One Slurm array of a farm's task array: its task k is the plan's task `offset` + k.
struct ArrayPart {
    std::string job;
    int offset = 0;
};

// A recorded job id: "JOB", or the arrays of one task array joined by ':', each "JOB" (offset 0)
// or "JOB+OFFSET" (see submitArray).
std::vector<ArrayPart> arrayParts(const std::string& id) {
    std::vector<ArrayPart> parts;
    std::istringstream items(id);
    for (std::string item; std::getline(items, item, ':');) {
        ArrayPart& part = parts.emplace_back();
        const std::size_t plus = item.find('+');
        part.job = item.substr(0, plus);
        if (plus != std::string::npos) std::from_chars(item.data() + plus + 1, item.data() + item.size(), part.offset);
    }
    return parts;
}

// The plain Slurm job ids of recorded ids, for --dependency, squeue and scancel.
std::vector<std::string> plainJobIds(const std::vector<std::string>& ids) {
    std::vector<std::string> plain;
    for (const std::string& id : ids)
        for (const ArrayPart& part : arrayParts(id)) plain.push_back(part.job);
    return plain;
}

}  // namespace

std::string SlurmFarmBackend::submitArray(const ArrayJob& job) {
    // Indices at or above the cluster's MaxArraySize go into further arrays, each shifted down by
    // its offset, which the task's command adds back: "$((SLURM_ARRAY_TASK_ID + OFFSET))". Such an
    // array's tasks redirect their output into the log of their own index, as %a cannot add.
    const int limit = maxArraySize();
    std::vector<std::vector<int>> blocks;
    for (int index : job.indices) {
        const std::size_t block = static_cast<std::size_t>(index / limit);
        if (blocks.size() <= block) blocks.resize(block + 1);
        blocks[block].push_back(index - static_cast<int>(block) * limit);
    }
    std::vector<std::string> submitted;
    try {
        for (std::size_t b = 0; b < blocks.size(); ++b) {
            if (blocks[b].empty()) continue;
            const int offset = static_cast<int>(b) * limit;
            std::string indices = arrayIndices(blocks[b]);
            if (job.maxParallel > 0) indices.append("%").append(std::to_string(job.maxParallel));
            const std::size_t at = job.logPattern.find("%a");
            const bool shifted = offset > 0 && at != std::string::npos;
            std::vector<std::string> argv = sbatchCommon(job.name, shifted ? "/dev/null" : job.logPattern, job.workDir);
            argv.push_back("--array=" + indices);
            if (job.cpusPerTask > 0) argv.push_back("--cpus-per-task=" + std::to_string(job.cpusPerTask));
            const std::string task = offset > 0 ? "\"$((SLURM_ARRAY_TASK_ID + " + std::to_string(offset) + "))\""
                                                : "\"$SLURM_ARRAY_TASK_ID\"";
            std::string wrap = shellCommand(job.command) + " " + task;
            if (shifted)
                wrap += " >> " + shellQuoted(job.logPattern.substr(0, at)) + task +
                        shellQuoted(job.logPattern.substr(at + 2)) + " 2>&1";
            argv.push_back("--wrap=" + wrap);
            const std::string id = parsedJobId(slurm(argv));
            submitted.push_back(offset > 0 ? id + "+" + std::to_string(offset) : id);
        }
    } catch (const SchedulerError&) {
        if (!submitted.empty()) cancel(submitted);  // all of the task array or none of it
        throw;
    }
    return joined(submitted, ':');
}

std::string SlurmFarmBackend::submitDependent(const SingleJob& job, const Dependencies& dependencies) {
    std::vector<std::string> argv = sbatchCommon(job.name, job.logPath, job.workDir);
    std::vector<std::string> conditions;
    if (!dependencies.afterOk.empty())
        conditions.push_back("afterok:" + joined(plainJobIds(dependencies.afterOk), ':'));
    if (!dependencies.afterAny.empty())
        conditions.push_back("afterany:" + joined(plainJobIds(dependencies.afterAny), ':'));
    if (!conditions.empty()) {
        argv.push_back("--dependency=" + joined(conditions, ','));
        argv.push_back("--kill-on-invalid-dep=yes");
    }
    argv.push_back("--wrap=" + shellCommand(job.command));
    return parsedJobId(slurm(argv));
}

std::vector<QueuedTask> SlurmFarmBackend::poll(const std::vector<std::string>& jobIds) {
    if (jobIds.empty()) return {};
    std::map<std::string, std::pair<std::string, int>> recorded;  // Slurm job id -> (recorded id, offset)
    for (const std::string& id : jobIds)
        for (const ArrayPart& part : arrayParts(id)) recorded[part.job] = {id, part.offset};
    CommandOutput r;
    try {
        r = runCommand({"squeue", "-h", "-r", "-j", joined(plainJobIds(jobIds), ','), "-o", "%F %K %T"});
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
        const auto found = recorded.find(jobId);
        t.jobId = found != recorded.end() ? found->second.first : jobId;
        std::from_chars(index.data(), index.data() + index.size(), t.index);  // "N/A" for a single job: stays -1
        if (t.index >= 0 && found != recorded.end()) t.index += found->second.second;
        t.state = state == "RUNNING" || state == "COMPLETING" || state == "CONFIGURING" ? QueueState::Running
                                                                                        : QueueState::Pending;
    }
    return tasks;
}

void SlurmFarmBackend::cancel(const std::vector<std::string>& jobIds) {
    if (jobIds.empty()) return;
    std::vector<std::string> argv = {"scancel"};
    const std::vector<std::string> plain = plainJobIds(jobIds);
    argv.insert(argv.end(), plain.begin(), plain.end());
    slurm(argv);
}

}  // namespace fluence::app
