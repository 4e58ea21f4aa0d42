#include "apps/farm_task.h"

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "apps/farm_process.h"
#include "apps/json.h"
#include "apps/render_command.h"
#include "output/atomic_file.h"

namespace fs = std::filesystem;

namespace fluence::app {

namespace {

void writeTaskRecord(const FarmPlan& plan, int index, const TaskRecord& record) {
    const std::string file = taskRecordPath(plan, index);
    const std::string json = "{\"task\": " + std::to_string(index) +
                             ", \"attempts\": " + std::to_string(record.attempts) +
                             ", \"exitCode\": " + (record.exitCode ? std::to_string(*record.exitCode) : "null") + "}\n";
    output::writeAtomically(file, [&](const std::string& temp) {
        std::ofstream out(temp, std::ios::binary);
        out << json;
        if (!out.flush()) throw output::OutputError("cannot write " + file);
    });
}

// A positive integer from the environment, or 0.
int positiveFromEnvironment(const char* name) {
    const char* text = std::getenv(name);
    int v = 0;
    if (!text) return 0;
    auto [end, error] = std::from_chars(text, text + std::char_traits<char>::length(text), v);
    return error == std::errc() && *end == '\0' && v > 0 ? v : 0;
}

bool failureInjectedFor(int index) {
    const char* text = std::getenv(kFarmFailTaskVariable);
    return text && std::string(text) == std::to_string(index);
}

std::string describe(const FarmPlan& plan, const FarmTask& task) {
    std::string what = "task " + std::to_string(task.index);
    if (task.frame) what += ", frame " + jsonNumber(*task.frame);
    if (plan.tiled())
        what += ", tile " + std::to_string(task.tile) + " of " + std::to_string(plan.tileColumns) + "x" +
                std::to_string(plan.tileRows);
    return what;
}

// Renders the task in this process; returns the render's exit code.
int renderTask(const FarmPlan& plan, const FarmTask& task) {
    const int slurmCpus = positiveFromEnvironment("SLURM_CPUS_PER_TASK");
    const std::vector<std::string> args = taskRenderArgs(plan, task, slurmCpus > 0 ? slurmCpus : plan.threadsPerTask);
    std::printf("fluence farm: %s: fluence render %s\n", describe(plan, task).c_str(), shellCommand(args).c_str());
    std::fflush(stdout);
    try {
        return runRender(parseRenderOptions(args));
    } catch (const UsageError& e) {
        printError(std::string("the plan's render arguments: ") + e.what());
        return kExitUsage;
    }
}

}  // namespace

std::string taskRecordPath(const FarmPlan& plan, int index) {
    return plan.path("tasks/task_" + std::to_string(index) + ".json");
}

std::optional<TaskRecord> readTaskRecord(const FarmPlan& plan, int index) {
    std::ifstream in(taskRecordPath(plan, index), std::ios::binary);
    if (!in) return std::nullopt;
    std::stringstream text;
    text << in.rdbuf();
    try {
        const JsonValue root = parseJson(text.str());
        TaskRecord record;
        record.attempts = root.at("attempts", "the task record").asInt("attempts");
        if (const JsonValue& code = root.at("exitCode", "the task record"); !code.isNull())
            record.exitCode = code.asInt("exitCode");
        return record;
    } catch (const JsonError&) {
        return std::nullopt;
    }
}

int runFarmTask(const std::string& folder, int index) {
    FarmPlan plan;
    try {
        plan = readFarmPlan(folder);
    } catch (const FarmPlanError& e) {
        printError(e.what());
        return kExitMissingInput;
    }
    if (index < 0 || index >= int(plan.tasks.size())) {
        printError("task " + std::to_string(index) + " is not in the plan " + plan.path(kFarmPlanFile) + " (0 to " +
                   std::to_string(plan.tasks.size() - 1) + ")");
        return kExitUsage;
    }
    const FarmTask& task = plan.tasks[index];
    TaskRecord record = readTaskRecord(plan, index).value_or(TaskRecord{});
    record.attempts += 1;
    record.exitCode.reset();
    int code = kExitOk;
    try {
        fs::create_directories(fs::path(plan.path(task.output)).parent_path());
        fs::create_directories(fs::path(taskRecordPath(plan, index)).parent_path());
        writeTaskRecord(plan, index, record);
    } catch (const std::exception& e) {  // filesystem_error or output::OutputError
        printError(e.what());
        return kExitOutput;
    }
    if (failureInjectedFor(index) && record.attempts == 1) {
        printError(describe(plan, task) + ": failing on purpose on its first attempt (test hook " +
                   std::string(kFarmFailTaskVariable) + "=" + std::to_string(index) + ")");
        code = kExitInternal;
    } else {
        code = renderTask(plan, task);
    }
    record.exitCode = code;
    try {
        writeTaskRecord(plan, index, record);
    } catch (const output::OutputError& e) {
        printError(e.what());
        return code == kExitOk ? kExitOutput : code;
    }
    return code;
}

}  // namespace fluence::app
