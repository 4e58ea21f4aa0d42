#include "apps/farm_local_backend.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <thread>

#include "apps/farm_process.h"

namespace fluence::app {

namespace {

std::string expandTaskIndex(std::string pattern, int index) {
    for (std::size_t at; (at = pattern.find("%a")) != std::string::npos;) pattern.replace(at, 2, std::to_string(index));
    return pattern;
}

}  // namespace

LocalFarmBackend::LocalFarmBackend(int maxJobs)
    : maxJobs_(maxJobs > 0 ? maxJobs : std::max(1, int(std::thread::hardware_concurrency()))) {}

std::string LocalFarmBackend::newJobId() {
    return "local-" + std::to_string(::getpid()) + "-" + std::to_string(++submitted_);
}

std::string LocalFarmBackend::submitArray(const ArrayJob& job) {
    const std::string id = newJobId();
    const int limit = job.maxParallel > 0 ? std::min(job.maxParallel, maxJobs_) : maxJobs_;
    std::map<pid_t, int> running;  // pid -> task index
    bool allOk = true;
    std::size_t next = 0;
    auto reapOne = [&] {
        int code = 0;
        const pid_t pid = waitForAny(code);
        const auto it = running.find(pid);
        if (it == running.end()) return;  // not one of ours
        allOk = allOk && code == 0;
        running.erase(it);
    };
    try {
        while (next < job.indices.size() || !running.empty()) {
            if (next < job.indices.size() && int(running.size()) < limit) {
                const int index = job.indices[next++];
                std::vector<std::string> argv = job.command;
                argv.push_back(std::to_string(index));
                running[startLogged(argv, expandTaskIndex(job.logPattern, index), job.workDir)] = index;
            } else {
                reapOne();
            }
        }
    } catch (const SpawnError& e) {
        while (!running.empty()) reapOne();  // let the tasks already started end
        throw SchedulerError(e.what());
    }
    succeeded_[id] = allOk;
    return id;
}

std::string LocalFarmBackend::submitDependent(const SingleJob& job, const Dependencies& dependencies) {
    const std::string id = newJobId();
    const bool ready =
        std::all_of(dependencies.afterOk.begin(), dependencies.afterOk.end(), [&](const std::string& dep) {
            const auto it = succeeded_.find(dep);
            return it != succeeded_.end() && it->second;
        });
    if (!ready) {
        std::printf("fluence farm: %s not run: a job it needs failed\n", job.name.c_str());
        succeeded_[id] = false;
        return id;
    }
    try {
        succeeded_[id] = waitForExit(startLogged(job.command, job.logPath, job.workDir)) == 0;
    } catch (const SpawnError& e) {
        throw SchedulerError(e.what());
    }
    return id;
}

std::vector<QueuedTask> LocalFarmBackend::poll(const std::vector<std::string>&) { return {}; }

void LocalFarmBackend::cancel(const std::vector<std::string>&) {}

}  // namespace fluence::app
