#include "apps/farm_plan.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "apps/cli_options.h"
#include "apps/frame_tokens.h"
#include "apps/json.h"
#include "output/atomic_file.h"

namespace fs = std::filesystem;

namespace fluence::app {

namespace {

int parseInt(const std::string& text, const std::string& whole) {
    int v = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || error != std::errc() || end != text.data() + text.size())
        throw UsageError("--frames expects A, A-B or A-BxK (integers), got '" + whole + "'");
    return v;
}

std::string frameJson(const std::optional<double>& frame) { return frame ? jsonNumber(*frame) : "null"; }

std::string intList(const std::vector<int>& values) {
    std::string out = "[";
    for (std::size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "") + std::to_string(values[i]);
    return out + "]";
}

std::optional<double> readFrame(const JsonValue& v, const std::string& what) {
    if (v.isNull()) return std::nullopt;
    return v.asNumber(what);
}

std::vector<int> readIntList(const JsonValue& v, const std::string& what) {
    std::vector<int> out;
    for (const JsonValue& item : v.asArray(what)) out.push_back(item.asInt(what + "[]"));
    return out;
}

std::string formatNumber(double v) {
    return v == std::floor(v) && std::abs(v) < 1e15 ? std::to_string(static_cast<long long>(v)) : jsonNumber(v);
}

}  // namespace

std::string FarmPlan::path(const std::string& relative) const { return (fs::path(folder) / relative).string(); }

std::vector<double> parseFrameRange(const std::string& text) {
    // The '-' between A and B is the first one after A's own sign.
    const std::size_t dash = text.find('-', text.starts_with("-") ? 1 : 0);
    const std::size_t times = text.find('x');
    const int first = parseInt(text.substr(0, std::min(dash, times)), text);
    if (dash == std::string::npos) {
        if (times != std::string::npos) throw UsageError("--frames A-BxK needs the last frame B, got '" + text + "'");
        return {double(first)};
    }
    const int last =
        parseInt(text.substr(dash + 1, times == std::string::npos ? std::string::npos : times - dash - 1), text);
    const int step = times == std::string::npos ? 1 : parseInt(text.substr(times + 1), text);
    if (last < first) throw UsageError("--frames " + text + ": the last frame comes before the first");
    if (step < 1) throw UsageError("--frames " + text + ": the step must be at least 1");
    std::vector<double> frames;
    for (long long f = first; f <= last; f += step) frames.push_back(double(f));
    return frames;
}

void planTasks(FarmPlan& plan, const std::vector<double>& frames) {
    const std::string name = fs::path(plan.scene).stem().string();
    std::vector<std::optional<double>> times(frames.begin(), frames.end());
    if (times.empty()) times.push_back(std::nullopt);
    plan.tasks.clear();
    plan.images.clear();
    for (const std::optional<double>& frame : times) {
        FarmImage& image = plan.images.emplace_back();
        image.frame = frame;
        const std::string base = frame ? expandFrameTokens(name + ".$F4", *frame) : name;
        image.output = base + ".exr";
        for (int tile = 0; tile < plan.tileColumns * plan.tileRows; ++tile) {
            FarmTask& task = plan.tasks.emplace_back();
            task.index = int(plan.tasks.size()) - 1;
            task.frame = frame;
            task.tile = tile;
            task.output = plan.tiled() ? "tiles/" + base + "_tile" + std::to_string(tile) + ".exr" : image.output;
            image.tasks.push_back(task.index);
        }
    }
}

std::vector<std::string> taskRenderArgs(const FarmPlan& plan, const FarmTask& task, int threads) {
    std::vector<std::string> args = {plan.scene};
    args.insert(args.end(), plan.renderArgs.begin(), plan.renderArgs.end());
    args.insert(args.end(), {"-o", plan.path(task.output), "-j", std::to_string(threads)});
    if (task.frame) args.insert(args.end(), {"-f", formatNumber(*task.frame)});
    // The task names its output exactly: an empty tile suffix leaves the path as given.
    if (plan.tiled())
        args.insert(args.end(), {"--tile-count", std::to_string(plan.tileColumns), std::to_string(plan.tileRows),
                                 "--tile-index", std::to_string(task.tile), "--tile-suffix", ""});
    return args;
}

void writeFarmPlan(const FarmPlan& plan) {
    std::string json =
        "{\n  \"fluenceFarmPlan\": 1,\n  \"scene\": " + jsonQuoted(plan.scene) + ",\n  \"renderArgs\": [";
    for (std::size_t i = 0; i < plan.renderArgs.size(); ++i) json += (i ? ", " : "") + jsonQuoted(plan.renderArgs[i]);
    json += "],\n  \"tiles\": [" + std::to_string(plan.tileColumns) + ", " + std::to_string(plan.tileRows) +
            "],\n  \"backend\": " + jsonQuoted(plan.backend) +
            ",\n  \"threadsPerTask\": " + std::to_string(plan.threadsPerTask) +
            ",\n  \"maxParallel\": " + std::to_string(plan.maxParallel) + ",\n  \"tasks\": [";
    for (std::size_t i = 0; i < plan.tasks.size(); ++i) {
        const FarmTask& t = plan.tasks[i];
        json += std::string(i ? "," : "") + "\n    {\"index\": " + std::to_string(t.index) +
                ", \"frame\": " + frameJson(t.frame) + ", \"tile\": " + std::to_string(t.tile) +
                ", \"output\": " + jsonQuoted(t.output) + "}";
    }
    json += "\n  ],\n  \"images\": [";
    for (std::size_t i = 0; i < plan.images.size(); ++i) {
        const FarmImage& im = plan.images[i];
        json += std::string(i ? "," : "") + "\n    {\"frame\": " + frameJson(im.frame) +
                ", \"output\": " + jsonQuoted(im.output) + ", \"tasks\": " + intList(im.tasks) + "}";
    }
    json += "\n  ],\n  \"submissions\": [";
    for (std::size_t i = 0; i < plan.submissions.size(); ++i) {
        const FarmSubmission& s = plan.submissions[i];
        json += std::string(i ? "," : "") + "\n    {\"backend\": " + jsonQuoted(s.backend) +
                ", \"tasks\": " + intList(s.tasks) + ", \"taskJob\": " + jsonQuoted(s.taskJob) +
                ", \"mergeJob\": " + jsonQuoted(s.mergeJob) + "}";
    }
    json += std::string(plan.submissions.empty() ? "" : "\n  ") + "]\n}\n";
    const std::string file = plan.path(kFarmPlanFile);
    output::writeAtomically(file, [&](const std::string& temp) {
        std::ofstream out(temp, std::ios::binary);
        out << json;
        if (!out.flush()) throw output::OutputError("cannot write " + file);
    });
}

FarmPlan readFarmPlan(const std::string& folder) {
    const std::string file = (fs::path(folder) / kFarmPlanFile).string();
    std::ifstream in(file, std::ios::binary);
    if (!in)
        throw FarmPlanError(file + ": no farm plan here (is " + folder +
                            " the output folder of `fluence farm submit`?)");
    std::stringstream text;
    text << in.rdbuf();
    FarmPlan plan;
    plan.folder = fs::absolute(folder).lexically_normal().string();
    try {
        const JsonValue root = parseJson(text.str());
        if (root.at("fluenceFarmPlan", "the plan").asInt("fluenceFarmPlan") != 1)
            throw JsonError("fluenceFarmPlan: this Fluence reads version 1 plans");
        plan.scene = root.at("scene", "the plan").asString("scene");
        for (const JsonValue& arg : root.at("renderArgs", "the plan").asArray("renderArgs"))
            plan.renderArgs.push_back(arg.asString("renderArgs[]"));
        const std::vector<int> tiles = readIntList(root.at("tiles", "the plan"), "tiles");
        if (tiles.size() != 2 || tiles[0] < 1 || tiles[1] < 1) throw JsonError("tiles must be [X, Y], both at least 1");
        plan.tileColumns = tiles[0];
        plan.tileRows = tiles[1];
        plan.backend = root.at("backend", "the plan").asString("backend");
        plan.threadsPerTask = root.at("threadsPerTask", "the plan").asInt("threadsPerTask");
        plan.maxParallel = root.at("maxParallel", "the plan").asInt("maxParallel");
        for (const JsonValue& t : root.at("tasks", "the plan").asArray("tasks")) {
            FarmTask& task = plan.tasks.emplace_back();
            task.index = t.at("index", "a task").asInt("tasks[].index");
            if (task.index != int(plan.tasks.size()) - 1) throw JsonError("tasks[].index must count from 0 in order");
            task.frame = readFrame(t.at("frame", "a task"), "tasks[].frame");
            task.tile = t.at("tile", "a task").asInt("tasks[].tile");
            task.output = t.at("output", "a task").asString("tasks[].output");
        }
        for (const JsonValue& im : root.at("images", "the plan").asArray("images")) {
            FarmImage& image = plan.images.emplace_back();
            image.frame = readFrame(im.at("frame", "an image"), "images[].frame");
            image.output = im.at("output", "an image").asString("images[].output");
            image.tasks = readIntList(im.at("tasks", "an image"), "images[].tasks");
            for (int index : image.tasks)
                if (index < 0 || index >= int(plan.tasks.size()))
                    throw JsonError("images[].tasks names no task: " + std::to_string(index));
        }
        for (const JsonValue& s : root.at("submissions", "the plan").asArray("submissions")) {
            FarmSubmission& sub = plan.submissions.emplace_back();
            sub.backend = s.at("backend", "a submission").asString("submissions[].backend");
            sub.tasks = readIntList(s.at("tasks", "a submission"), "submissions[].tasks");
            sub.taskJob = s.at("taskJob", "a submission").asString("submissions[].taskJob");
            sub.mergeJob = s.at("mergeJob", "a submission").asString("submissions[].mergeJob");
        }
    } catch (const JsonError& e) {
        throw FarmPlanError(file + ": " + e.what());
    }
    return plan;
}

}  // namespace fluence::app
