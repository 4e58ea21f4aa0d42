#include "apps/review_static.h"

#include <filesystem>
#include <fstream>

#include "apps/json.h"
#include "apps/review_exr.h"
#include "output/atomic_file.h"
#include "review/review_assets.h"

namespace fluence::app {

namespace {

std::string base64(const std::string& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        std::uint32_t word = 0;
        for (std::size_t k = 0; k < 3; ++k) word = word << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        for (std::size_t k = 0; k < 4; ++k) out += k <= n ? digits[(word >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

void writeFile(const std::filesystem::path& path, const std::string& text) {
    output::writeAtomically(path.string(), [&](const std::string& tempPath) {
        std::ofstream file(tempPath, std::ios::binary);
        file.write(text.data(), static_cast<std::streamsize>(text.size()));
        file.close();
        if (!file) throw std::runtime_error("the file could not be written");
    });
}

// Appends `"key":value` for the answer to `request` with `args`; throws ReviewInputError with the
// failure's message (which names the file) when it is an error.
void addAnswer(std::string& data, const ReviewApi& api, const std::string& request,
               const std::vector<std::string>& args) {
    const ReviewAnswer answer = api.answer(request, args);
    if (answer.status != 200) throw ReviewInputError(answer.error);
    std::string key = request;
    for (const std::string& a : args) key += "|" + a;
    data += (data.size() > 1 ? ",\n" : "") + jsonQuoted(key) + ":" +
            (answer.contentType == "application/json" ? answer.body : jsonQuoted(base64(answer.body)));
}

}  // namespace

void writeStaticReview(const ReviewApi& api, const std::string& outputDir) {
    std::error_code ec;
    std::filesystem::create_directories(outputDir, ec);
    if (ec) throw output::outputError(outputDir, ec.message());
    std::string data = "{";
    addAnswer(data, api, "files", {});
    for (const ReviewFile& file : api.files()) {
        addAnswer(data, api, "image", {file.name});
        addAnswer(data, api, "menus", {file.name});
        for (const ReviewLayer& layer : readReviewImage(file.path).layers)
            addAnswer(data, api, "pixels", {file.name, layer.name});
        const color::DisplayMenus menus = api.pipelineFor(file).menus();
        std::vector<std::string> looks{""};
        looks.insert(looks.end(), menus.looks.begin(), menus.looks.end());
        for (const std::string& display : menus.displays)
            for (const std::string& view : menus.views.at(display))
                for (const std::string& look : looks) addAnswer(data, api, "shader", {file.name, display, view, look});
    }
    const std::filesystem::path dir(outputDir);
    writeFile(dir / "data.js", "window.FLUENCE_REVIEW_DATA = " + data + "};\n");
    for (const review::ReviewAsset& asset : review::reviewAssets()) writeFile(dir / asset.name, asset.text);
}

}  // namespace fluence::app
