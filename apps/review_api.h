// The answers of `fluence review`'s page requests, shared by the HTTP server (apps/review_server.h)
// and the static export (apps/review_static.h), which writes the same answers into a file:
//   files                          {"config","files":[{"name","sequence","frame"}]}
//   image   FILE                   the EXR's layers, attributes and Cryptomatte manifests (review_exr.h)
//   pixels  FILE LAYER             the layer's channels, raw float16/float32 (binary)
//   menus   FILE                   the displays, views and looks of the file's OCIO config
//   shader  FILE DISPLAY VIEW LOOK the GLSL ES 3.0 shader and LUTs OCIO generates (color/display_pipeline.h)
// A file's OCIO config is the one its `fluence/ocioConfig` attribute names when that file exists,
// else $OCIO, else the built-in config.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "apps/review_files.h"
#include "color/display_pipeline.h"

namespace fluence::app {

struct ReviewAnswer {
    int status = 200;
    std::string contentType;
    std::string body;
    std::string error{};  // a failure's message, as its JSON body holds it (status != 200)
};

class ReviewApi {
public:
    explicit ReviewApi(std::vector<ReviewFile> files);

    const std::vector<ReviewFile>& files() const { return files_; }
    // The requests and the names of their arguments, in order (the server's query parameters).
    static const std::map<std::string, std::vector<std::string>>& requests();
    // `request` is one of the names above, `arguments` its arguments in that order. Unknown requests
    // and files answer 404, an unsafe file name 403, an unreadable file or unknown display 422.
    ReviewAnswer answer(const std::string& request, const std::vector<std::string>& arguments) const;

    // The pipeline of `file`'s config (cached by config).
    color::DisplayPipeline pipelineFor(const ReviewFile& file) const;

private:
    std::vector<ReviewFile> files_;
    mutable std::mutex mutex_;
    mutable std::map<std::string, color::DisplayPipeline> pipelines_;  // by config path ("" for the default)
};

// {"displays":[..],"views":{display:[..]},"looks":[..],"defaultDisplay":..,"defaultViews":{..},"config":..}
std::string displayMenusJson(const color::DisplayMenus& menus, const std::string& configDescription);
// {"functionName","text","uniforms":[{"name","setting"}],"textures":[{..,"values":[..]}]}
std::string gpuShaderJson(const color::GpuDisplayShader& shader);

}  // namespace fluence::app
