#include "apps/review_api.h"

#include <filesystem>

#include "apps/json.h"
#include "apps/review_exr.h"
#include "color/color_management.h"

namespace fluence::app {

namespace {

template <class Range, class Format>
std::string jsonArray(const Range& items, Format format) {
    std::string json = "[";
    bool first = true;
    for (const auto& item : items) {
        json += (first ? "" : ",") + format(item);
        first = false;
    }
    return json + "]";
}

std::string quotedArray(const std::vector<std::string>& items) { return jsonArray(items, jsonQuoted); }

std::string attribute(const ReviewImage& image, const std::string& name) {
    for (const auto& [key, value] : image.attributes)
        if (key == name) return value;
    return {};
}

ReviewAnswer json(std::string body) { return {200, "application/json", std::move(body)}; }
ReviewAnswer failure(int status, const std::string& message) {
    return {status, "application/json", "{\"error\":" + jsonQuoted(message) + "}", message};
}

}  // namespace

std::string displayMenusJson(const color::DisplayMenus& menus, const std::string& configDescription) {
    std::string views, defaults;
    for (const std::string& d : menus.displays) {
        views += (views.empty() ? "" : ",") + jsonQuoted(d) + ":" + quotedArray(menus.views.at(d));
        defaults += (defaults.empty() ? "" : ",") + jsonQuoted(d) + ":" + jsonQuoted(menus.defaultViews.at(d));
    }
    return "{\"config\":" + jsonQuoted(configDescription) + ",\"displays\":" + quotedArray(menus.displays) +
           ",\"views\":{" + views + "},\"looks\":" + quotedArray(menus.looks) +
           ",\"defaultDisplay\":" + jsonQuoted(menus.defaultDisplay) + ",\"defaultViews\":{" + defaults + "}}";
}

std::string gpuShaderJson(const color::GpuDisplayShader& shader) {
    const std::string uniforms = jsonArray(shader.uniforms, [](const color::GpuUniform& u) {
        return "{\"name\":" + jsonQuoted(u.name) + ",\"setting\":" + jsonQuoted(u.setting) + "}";
    });
    const std::string textures = jsonArray(shader.textures, [](const color::GpuLutTexture& t) {
        return "{\"textureName\":" + jsonQuoted(t.textureName) + ",\"samplerName\":" + jsonQuoted(t.samplerName) +
               ",\"width\":" + std::to_string(t.width) + ",\"height\":" + std::to_string(t.height) +
               ",\"depth\":" + std::to_string(t.depth) + ",\"channels\":" + std::to_string(t.channels) +
               ",\"linear\":" + (t.linearInterpolation ? "true" : "false") +
               ",\"values\":" + jsonArray(t.values, [](float v) { return jsonNumber(v); }) + "}";
    });
    return "{\"functionName\":" + jsonQuoted(shader.functionName) + ",\"text\":" + jsonQuoted(shader.text) +
           ",\"uniforms\":" + uniforms + ",\"textures\":" + textures + "}";
}

const std::map<std::string, std::vector<std::string>>& ReviewApi::requests() {
    static const std::map<std::string, std::vector<std::string>> names = {
        {"files", {}},
        {"image", {"file"}},
        {"pixels", {"file", "layer"}},
        {"menus", {"file"}},
        {"shader", {"file", "display", "view", "look"}}};
    return names;
}

ReviewApi::ReviewApi(std::vector<ReviewFile> files) : files_(std::move(files)) {}

color::DisplayPipeline ReviewApi::pipelineFor(const ReviewFile& file) const {
    std::string config = attribute(readReviewImage(file.path), "fluence/ocioConfig");
    const std::size_t fromEnv = config.find(" (from $OCIO)");
    if (fromEnv != std::string::npos) config.resize(fromEnv);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(config, ec)) config.clear();
    std::lock_guard lock(mutex_);
    auto it = pipelines_.find(config);
    if (it == pipelines_.end()) it = pipelines_.emplace(config, color::DisplayPipeline::open(config)).first;
    return it->second;
}

ReviewAnswer ReviewApi::answer(const std::string& request, const std::vector<std::string>& args) const {
    const auto known = requests().find(request);
    if (known == requests().end() || args.size() != known->second.size())
        return failure(404, "no such request: " + request);
    if (request == "files") {
        return json("{\"files\":" +
                    jsonArray(files_,
                              [](const ReviewFile& f) {
                                  return "{\"name\":" + jsonQuoted(f.name) + ",\"sequence\":" + jsonQuoted(f.sequence) +
                                         ",\"frame\":" + std::to_string(f.frame) + "}";
                              }) +
                    "}");
    }
    if (isUnsafeReviewName(args[0])) return failure(403, "refused file name: " + args[0]);
    const std::optional<ReviewFile> file = findReviewFile(files_, args[0]);
    if (!file) return failure(404, "not a reviewed file: " + args[0]);
    try {
        if (request == "image") return json(reviewImageJson(readReviewImage(file->path)));
        if (request == "pixels") return {200, "application/octet-stream", readReviewLayerPixels(file->path, args[1])};
        const color::DisplayPipeline pipeline = pipelineFor(*file);
        if (request == "menus") return json(displayMenusJson(pipeline.menus(), pipeline.configDescription()));
        const std::string space = pipeline.inputSpace(attribute(readReviewImage(file->path), "colorSpace"));
        return json(gpuShaderJson(pipeline.gpuShader(space, {args[1], args[2], args[3], 0.0, 1.0})));
    } catch (const ReviewInputError& e) {
        return failure(422, e.what());
    } catch (const color::ColorError& e) {
        return failure(422, e.what());
    }
}

}  // namespace fluence::app
