#include "apps/render_products.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <regex>
#include <set>

#include "apps/light_path_aovs.h"
#include "core/name_table.h"
#include "delegate/prim_reader.h"

namespace fluence::app {

namespace {

using delegate::SceneError;
using integrators::PixelFilter;

bool contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

// Cryptomatte vars are written by the Cryptomatte layers (apps/cryptomatte_layers.h).
bool isCryptomatteVar(const delegate::RenderVarDesc& desc) {
    return desc.sourceType == "raw" && (desc.sourceName == "CryptoObject" || desc.sourceName == "CryptoMaterial");
}

// What a dataType token says: components, pixel type, and whether it is a colour role.
struct DataType {
    int components = 3;
    output::PixelType type = output::PixelType::Float;
    bool colourRole = false;
};

std::optional<DataType> parseDataType(const std::string& token) {
    // A scalar type with an optional count (float, half3, int2), or a role with a count and a
    // precision suffix (color3f, normal3h, texCoord2d).
    static const std::regex kScalar("(half|float|double|int|uint)([234]?)");
    static const std::regex kRole("(color|vector|normal|point|texCoord)([234])([hfd])");
    std::smatch m;
    DataType t;
    if (std::regex_match(token, m, kScalar)) {
        t.components = m[2].length() ? std::stoi(m[2]) : 1;
        const std::string base = m[1];
        t.type = base == "half"                    ? output::PixelType::Half
                 : base == "int" || base == "uint" ? output::PixelType::Uint
                                                   : output::PixelType::Float;
        return t;
    }
    if (std::regex_match(token, m, kRole)) {
        t.components = std::stoi(m[2]);
        t.type = m[3] == "h" ? output::PixelType::Half : output::PixelType::Float;
        t.colourRole = m[1] == "color";
        if (t.colourRole && t.components < 3) return std::nullopt;
        return t;
    }
    return std::nullopt;
}

// The film's channels a source reads (Film::channelNames), for `components` of them.
std::vector<std::string> filmChannels(VarSource source, const std::string& name, int components) {
    switch (source) {
        case VarSource::Beauty:
            return components == 4 ? std::vector<std::string>{"R", "G", "B", "A"}
                                   : std::vector<std::string>{"R", "G", "B"};
        case VarSource::Alpha: return {"A"};
        case VarSource::Albedo: return {"albedo.R", "albedo.G", "albedo.B"};
        case VarSource::Normal: return {"N.X", "N.Y", "N.Z"};
        case VarSource::Depth: return {"Z"};
        case VarSource::SampleCount: return {"sampleCount"};
        case VarSource::LightPath: return {name + ".R", name + ".G", name + ".B"};
        case VarSource::Primvar:
        case VarSource::MotionVector: break;
    }
    return {};
}

// Whether a var's AOV name is one of its source's names, ignoring case ("Beauty", "Z").
bool namedLikeItsSource(VarSource source, const std::string& aovName) {
    auto lower = [](std::string text) {
        for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
        return text;
    };
    const std::vector<std::string>& names = rawSourceNames(source);
    return std::any_of(names.begin(), names.end(), [&](const std::string& n) { return lower(n) == lower(aovName); });
}

// The channel names a var writes: see the header.
std::vector<std::string> channelNames(VarSource source, const std::string& aovName, const DataType& type) {
    if (source == VarSource::Beauty && namedLikeItsSource(source, aovName))
        return filmChannels(VarSource::Beauty, "", type.components);
    if (source == VarSource::Alpha && namedLikeItsSource(source, aovName)) return {"A"};
    if (source == VarSource::Depth && namedLikeItsSource(source, aovName)) return {"Z"};
    if (type.components == 1) return {aovName};
    static const char* kColour[] = {".R", ".G", ".B", ".A"};
    static const char* kVector[] = {".X", ".Y", ".Z", ".W"};
    std::vector<std::string> names;
    for (int c = 0; c < type.components; ++c) names.push_back(aovName + (type.colourRole ? kColour : kVector)[c]);
    return names;
}

// The filters a source takes, its default first.
std::vector<PixelFilter> filtersOf(VarSource source) {
    switch (source) {
        case VarSource::Depth: return {PixelFilter::Min, PixelFilter::Box, PixelFilter::Max, PixelFilter::Closest};
        case VarSource::Albedo:
        case VarSource::Normal:
        case VarSource::MotionVector:
        case VarSource::Primvar: return {PixelFilter::Box, PixelFilter::Min, PixelFilter::Max, PixelFilter::Closest};
        default: return {PixelFilter::Box};
    }
}

PixelFilter chosenFilter(const delegate::RenderVarDesc& desc, VarSource source,
                         const std::function<void(const std::string&, const std::string&)>& warn) {
    static const std::pair<const char*, PixelFilter> kNames[] = {{"box", PixelFilter::Box},
                                                                 {"min", PixelFilter::Min},
                                                                 {"max", PixelFilter::Max},
                                                                 {"closest", PixelFilter::Closest}};
    const std::vector<PixelFilter> allowed = filtersOf(source);
    if (desc.filter.empty()) return allowed.front();
    for (const auto& [name, filter] : kNames)
        if (desc.filter == name && std::find(allowed.begin(), allowed.end(), filter) != allowed.end()) return filter;
    warn(desc.path, "fluence:filter '" + desc.filter + "' is not supported for this source (" +
                        (allowed.size() > 1 ? "box, min, max or closest" : "box only") + "); using box");
    return PixelFilter::Box;
}

// The source of a raw or primvar RenderVar (lpe vars are read by lightPathAovs). Throws SceneError.
ProductVar varOf(const delegate::RenderVarDesc& desc,
                 const std::function<void(const std::string&, const std::string&)>& warn) {
    ProductVar var;
    var.path = desc.path;
    std::optional<DataType> type = parseDataType(desc.dataType);
    if (!type)
        throw SceneError("RenderVar " + desc.path + ": dataType '" + desc.dataType +
                         "' is not a type Fluence writes (half, float, int, their 2-4 component forms, and "
                         "color/vector/normal/point/texCoord types)");
    int needs = 0;  // the components the source has (0: any of 1 to 4)
    if (desc.sourceType == "raw") {
        static const VarSource kRaw[] = {VarSource::Beauty,      VarSource::Alpha, VarSource::Albedo,
                                         VarSource::Normal,      VarSource::Depth, VarSource::SampleCount,
                                         VarSource::MotionVector};
        const VarSource* found = std::find_if(std::begin(kRaw), std::end(kRaw), [&](VarSource s) {
            return contains(rawSourceNames(s), desc.sourceName);
        });
        if (found == std::end(kRaw))
            throw SceneError(
                "RenderVar " + desc.path + ": raw sourceName '" + desc.sourceName +
                "' is not an output of Fluence (see docs/RENDER_PRODUCTS.md: color/Ci/C, alpha/a, albedo, N/normal, "
                "depth/z/Z, sampleCount, motionvector)");
        var.source = *found;
        needs = var.source == VarSource::Beauty                                      ? (type->components == 4 ? 4 : 3)
                : var.source == VarSource::Albedo || var.source == VarSource::Normal ? 3
                                                                                     : 1;
    } else if (desc.sourceType == "primvar") {
        var.source = VarSource::Primvar;
        var.name = desc.sourceName.starts_with("primvars:") ? desc.sourceName.substr(9) : desc.sourceName;
        if (var.name.empty())
            throw SceneError("RenderVar " + desc.path + ": sourceType primvar needs a sourceName (primvars:NAME)");
    } else {
        throw SceneError("RenderVar " + desc.path + ": sourceType '" + desc.sourceType +
                         "' is not one Fluence writes (raw, primvar, lpe)");
    }
    if (needs == 1 && type->components > 1)
        warn(desc.path, "dataType " + desc.dataType + " has " + std::to_string(type->components) +
                            " components; source '" + desc.sourceName + "' gives 1, which is written to each");
    else if (needs && type->components != needs)
        throw SceneError("RenderVar " + desc.path + ": dataType " + desc.dataType + " has " +
                         std::to_string(type->components) + (type->components == 1 ? " component" : " components") +
                         "; source '" + desc.sourceName + "' gives " + std::to_string(needs));
    var.components = needs == 1 ? 1 : type->components;
    var.type = type->type;
    var.filter = chosenFilter(desc, var.source, warn);
    var.colour = var.source == VarSource::Beauty || var.source == VarSource::Alpha || var.source == VarSource::Albedo ||
                 (var.source == VarSource::Primvar && type->colourRole);
    var.channels = channelNames(var.source, desc.aovName, *type);
    return var;
}

ProductVar lightPathVar(const integrators::LightPathAov& aov, const delegate::RenderProductDesc* product) {
    ProductVar var;
    var.source = VarSource::LightPath;
    var.name = aov.name;
    var.channels = filmChannels(VarSource::LightPath, aov.name, 3);
    if (product)
        for (const delegate::RenderVarDesc& desc : product->vars)
            if (desc.sourceType == "lpe" && primName(desc.path) == aov.name) {
                var.path = desc.path;
                std::optional<DataType> type = parseDataType(desc.dataType);
                if (!type || type->components != 3)
                    throw SceneError("RenderVar " + desc.path +
                                     ": an lpe var's dataType must have 3 components (color3f, color3h, ...), got '" +
                                     desc.dataType + "'");
                var.type = type->type;
            }
    return var;
}

ProductVar filmVar(VarSource source, int components, bool colour) {
    ProductVar var;
    var.source = source;
    var.components = components;
    var.colour = colour;
    var.channels = filmChannels(source, "", components);
    if (source == VarSource::Depth) var.filter = PixelFilter::Min;
    return var;
}

// The vars of a product without RenderVars: the film's own channels (Film::channelNames).
std::vector<ProductVar> defaultVars() {
    return {filmVar(VarSource::Beauty, 4, true), filmVar(VarSource::Albedo, 3, true),
            filmVar(VarSource::Normal, 3, false), filmVar(VarSource::Depth, 1, false),
            filmVar(VarSource::SampleCount, 1, false)};
}

// Whether the film holds a var as it is asked (else the first-hit pass computes it).
bool fromFilm(const ProductVar& var) {
    if (var.source == VarSource::Primvar || var.source == VarSource::MotionVector) return false;
    if (var.source == VarSource::Depth) return var.filter == PixelFilter::Min;
    return var.filter == PixelFilter::Box;
}

integrators::FirstHitAov firstHitAovOf(const ProductVar& var) {
    integrators::FirstHitAov aov;
    aov.source = var.source == VarSource::Depth          ? integrators::FirstHitSource::Depth
                 : var.source == VarSource::Normal       ? integrators::FirstHitSource::Normal
                 : var.source == VarSource::Albedo       ? integrators::FirstHitSource::Albedo
                 : var.source == VarSource::MotionVector ? integrators::FirstHitSource::MotionVector
                                                         : integrators::FirstHitSource::Primvar;
    aov.primvar = var.name;
    aov.components = var.components;
    aov.filter = var.filter;
    return aov;
}

bool sameFirstHitAov(const integrators::FirstHitAov& a, const integrators::FirstHitAov& b) {
    return a.source == b.source && a.primvar == b.primvar && a.components == b.components && a.filter == b.filter;
}

// The compression a product is written with: lossless whenever it has data channels.
std::string compressionOf(const delegate::RenderProductDesc& product, const std::vector<ProductVar>& vars,
                          const std::function<void(const std::string&, const std::string&)>& warn) {
    if (product.compression.empty()) return "zip";
    const std::string method = product.compression.substr(0, product.compression.find(':'));
    static const std::vector<std::string> kLossless{"none", "rle", "zips", "zip", "piz"};
    static const std::vector<std::string> kLossy{"pxr24", "b44", "b44a", "dwaa", "dwab"};
    if (contains(kLossless, method)) return product.compression;
    if (!contains(kLossy, method))
        throw SceneError("RenderProduct " + product.path + ": driver:parameters:OpenEXR:compression '" +
                         product.compression +
                         "' is not one of none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab");
    const bool data = std::any_of(vars.begin(), vars.end(),
                                  [](const ProductVar& v) { return !v.colour || v.type == output::PixelType::Uint; });
    if (!data) return product.compression;
    warn(product.path,
         "lossy compression '" + product.compression + "' would alter its data channels; written with zip");
    return "zip";
}

std::string defaultOutput(const std::string& sceneStem, const std::string& suffix, int frameCount) {
    return sceneStem + suffix + (frameCount > 1 ? ".$F4.exr" : ".exr");
}

// The vars of one RenderProduct (nullptr: the default product), with the implicit beauty.
std::vector<ProductVar> productVars(const delegate::RenderProductDesc* product,
                                    const std::vector<integrators::LightPathAov>& lightPaths,
                                    const std::function<void(const std::string&, const std::string&)>& warn) {
    std::vector<ProductVar> vars;
    if (!product || std::all_of(product->vars.begin(), product->vars.end(),
                                [](const auto& v) { return v.sourceType == "lpe" || isCryptomatteVar(v); }))
        vars = defaultVars();
    if (product)
        for (const delegate::RenderVarDesc& desc : product->vars)
            if (desc.sourceType != "lpe" && !isCryptomatteVar(desc)) vars.push_back(varOf(desc, warn));
    for (const integrators::LightPathAov& aov : lightPaths) vars.push_back(lightPathVar(aov, product));
    // The beauty in front, unless a var writes R, and without the channels vars write.
    auto writes = [&](const std::string& channel) {
        return std::any_of(vars.begin(), vars.end(),
                           [&](const ProductVar& v) { return contains(v.channels, channel); });
    };
    if (!writes("R")) {
        const bool alpha = !writes("A");
        vars.insert(vars.begin(), filmVar(VarSource::Beauty, 3, true));
        if (alpha) vars.insert(vars.begin() + 1, filmVar(VarSource::Alpha, 1, true));
    }
    // Each channel once.
    std::set<std::string> seen;
    for (const ProductVar& var : vars)
        for (const std::string& channel : var.channels)
            if (!seen.insert(channel).second)
                throw SceneError((var.path.empty() ? std::string("--lpe") : "RenderVar " + var.path) +
                                 ": the channel '" + channel + "' is written by another var of " +
                                 (product ? "RenderProduct " + product->path : std::string("the product")));
    return vars;
}

}  // namespace

PixelWindow PixelWindow::intersect(const PixelWindow& o) const {
    return {std::max(x0, o.x0), std::max(y0, o.y0), std::min(x1, o.x1), std::min(y1, o.y1)};
}

PixelWindow PixelWindow::unite(const PixelWindow& o) const {
    if (empty()) return o;
    if (o.empty()) return *this;
    return {std::min(x0, o.x0), std::min(y0, o.y0), std::max(x1, o.x1), std::max(y1, o.y1)};
}

PixelWindow pixelWindowOf(const std::array<float, 4>& ndc, std::pair<int, int> resolution) {
    const double w = resolution.first, h = resolution.second;
    auto first = [](double edge) {
        return int(std::ceil(edge - 0.5));
    };  // the first pixel whose centre is at or past edge
    return {first(w * ndc[0]), first(h * (1.0 - ndc[3])), first(w * ndc[2]), first(h * (1.0 - ndc[1]))};
}

const std::vector<std::string>& rawSourceNames(VarSource source) {
    static const std::vector<std::string> kBeauty{"color", "Ci", "C", "C.*", "beauty", "rgb", "rgba", "RGBA"};
    static const std::vector<std::string> kAlpha{"alpha", "a", "A"};
    static const std::vector<std::string> kAlbedo{"albedo"};
    static const std::vector<std::string> kNormal{"N", "normal", "Nn"};
    static const std::vector<std::string> kDepth{"depth", "z", "Z", "Pz"};
    static const std::vector<std::string> kSampleCount{"sampleCount"};
    static const std::vector<std::string> kMotionVector{"motionvector", "motionVector"};
    static const std::vector<std::string> kNone;
    switch (source) {
        case VarSource::Beauty: return kBeauty;
        case VarSource::Alpha: return kAlpha;
        case VarSource::Albedo: return kAlbedo;
        case VarSource::Normal: return kNormal;
        case VarSource::Depth: return kDepth;
        case VarSource::SampleCount: return kSampleCount;
        case VarSource::MotionVector: return kMotionVector;
        default: return kNone;
    }
}

PixelWindow PlannedRender::window() const {
    PixelWindow all;
    for (const PlannedProduct& p : products) all = all.unite(p.window);
    return all;
}

std::set<std::string> RenderPlan::primvars() const {
    std::set<std::string> names;
    for (const PlannedRender& render : renders)
        for (const integrators::FirstHitAov& aov : render.firstHitAovs)
            if (aov.source == integrators::FirstHitSource::Primvar) names.insert(aov.primvar);
    return names;
}

RenderPlan planRenders(const std::optional<delegate::RenderSettingsDesc>& settings, const RenderOptions& opt,
                       const std::string& sceneStem,
                       const std::function<void(const std::string&, const std::string&)>& warn) {
    std::vector<const delegate::RenderProductDesc*> products;
    if (settings)
        for (const delegate::RenderProductDesc& p : settings->products) products.push_back(&p);
    if (products.empty()) products.push_back(nullptr);  // the default product

    RenderPlan plan;
    std::vector<std::pair<std::string, std::string>> outputs;  // pattern, product
    for (std::size_t i = 0; i < products.size(); ++i) {
        const delegate::RenderProductDesc* desc = products[i];
        const std::pair<int, int> resolution = opt.resolution ? *opt.resolution
                                               : desc         ? desc->resolution
                                               : settings     ? settings->resolution
                                                              : std::pair<int, int>{kDefaultWidth, kDefaultHeight};
        const std::string camera = !opt.camera.empty() ? opt.camera
                                   : desc              ? desc->cameraPath
                                   : settings          ? settings->cameraPath
                                                       : "";
        const render::ImageFraming framing = desc       ? desc->framing
                                             : settings ? settings->framing
                                                        : render::ImageFraming{};

        PlannedProduct product;
        product.path = desc ? desc->path : "";
        const std::string label = desc ? "RenderProduct " + desc->path : std::string("the output");
        product.outputPattern =
            i == 0 && !opt.output.empty() ? opt.output
            : desc && !desc->productName.empty()
                ? desc->productName
                : defaultOutput(sceneStem, i == 0 ? "" : "_" + primName(desc->path), opt.frameCount);
        for (const auto& [pattern, other] : outputs)
            if (pattern == product.outputPattern)
                throw SceneError(label + ": writes " + pattern + ", as " + other + " does");
        outputs.emplace_back(product.outputPattern, label);

        const PixelWindow full{0, 0, resolution.first, resolution.second};
        product.window = desc ? pixelWindowOf(desc->dataWindowNdc, resolution) : full;
        if (product.window.intersect(full) != product.window)
            warn(product.path,
                 "dataWindowNDC reaches outside the image (overscan), which Fluence does not render; clipped to the "
                 "image");
        product.window = product.window.intersect(full);
        if (product.window.empty())
            throw SceneError(label + ": dataWindowNDC holds no pixel of the " + std::to_string(resolution.first) + "x" +
                             std::to_string(resolution.second) + " image");

        const std::vector<integrators::LightPathAov> lightPaths =
            lightPathAovs(desc, i == 0 ? opt.lightPaths : std::vector<LightPathOption>{});
        product.vars = productVars(desc, lightPaths, warn);
        product.compression = desc ? compressionOf(*desc, product.vars, warn) : "zip";

        // Its render: one of the same camera, resolution and framing, else a new one.
        auto same = std::find_if(plan.renders.begin(), plan.renders.end(), [&](const PlannedRender& r) {
            return r.cameraPath == camera && r.resolution == resolution &&
                   r.framing.pixelAspectRatio == framing.pixelAspectRatio && r.framing.conform == framing.conform;
        });
        PlannedRender& render = same != plan.renders.end()
                                    ? *same
                                    : plan.renders.emplace_back(PlannedRender{camera, resolution, framing, {}, {}, {}});
        for (const integrators::LightPathAov& aov : lightPaths) {
            auto existing = std::find_if(render.lightPaths.begin(), render.lightPaths.end(),
                                         [&](const auto& a) { return a.name == aov.name; });
            if (existing == render.lightPaths.end())
                render.lightPaths.push_back(aov);
            else if (existing->expression.text() != aov.expression.text())
                throw SceneError(label + ": light path layer '" + aov.name + "' is '" + aov.expression.text() +
                                 "' here but '" + existing->expression.text() +
                                 "' in another product of the same render");
        }
        if (render.lightPaths.size() > std::size_t(kMaxLightPathLayers))
            throw SceneError(label + ": its render needs " + std::to_string(render.lightPaths.size()) +
                             " light path layers; at most " + std::to_string(kMaxLightPathLayers));
        for (ProductVar& var : product.vars) {
            if (fromFilm(var)) continue;
            const integrators::FirstHitAov aov = firstHitAovOf(var);
            auto found = std::find_if(render.firstHitAovs.begin(), render.firstHitAovs.end(),
                                      [&](const integrators::FirstHitAov& a) { return sameFirstHitAov(a, aov); });
            var.firstHitAov = int(found - render.firstHitAovs.begin());
            if (found == render.firstHitAovs.end()) render.firstHitAovs.push_back(aov);
        }
        render.products.push_back(std::move(product));
    }
    return plan;
}

const delegate::RenderProductDesc* findProduct(const std::optional<delegate::RenderSettingsDesc>& settings,
                                               const std::string& path) {
    if (!settings || path.empty()) return nullptr;
    for (const delegate::RenderProductDesc& p : settings->products)
        if (p.path == path) return &p;
    return nullptr;
}

void describeProductHeader(output::ExrHeader& header, const render::Camera& camera, const PixelWindow& written,
                           std::pair<int, int> resolution) {
    // Imath's M44f is for row vectors: the transpose of Fluence's column-vector matrices.
    auto m44f = [](const Matrix4& m) {
        std::array<float, 16> values{};
        for (int row = 0; row < 4; ++row)
            for (int column = 0; column < 4; ++column)
                values[std::size_t(4 * column + row)] = float(m.m[std::size_t(row)][std::size_t(column)]);
        return values;
    };
    header.matrices.push_back({"worldToCamera", m44f(camera.worldToCamera())});
    header.matrices.push_back({"worldToNDC", m44f(camera.worldToNdc())});
    // The ASWF Color Interop Forum's IDs of the spaces Fluence renders in.
    static const std::pair<const char*, const char*> kInteropIds[] = {
        {"lin_rec709", "lin_rec709_scene"}, {"ACEScg", "lin_ap1_scene"}, {"acescg", "lin_ap1_scene"}};
    for (const auto& [space, id] : kInteropIds)
        if (header.colorSpace == space) header.colorInteropId = id;
    if (written == PixelWindow{0, 0, resolution.first, resolution.second}) return;
    header.x = written.x0;
    header.y = written.y0;
    header.fullWidth = resolution.first;
    header.fullHeight = resolution.second;
}

Image productImage(const PlannedProduct& product, const PixelWindow& window, const Image& film, const Image& firstHit,
                   const PixelWindow& filmWindow, output::ExrHeader& header) {
    struct Source {
        const Image* image;
        int channel;
    };
    std::vector<std::string> names;
    std::vector<Source> sources;
    header.channelTypes.clear();
    header.dataChannels.clear();
    for (const ProductVar& var : product.vars) {
        const std::vector<std::string> from = filmChannels(var.source, var.name, var.components);
        if (var.source == VarSource::LightPath && film.channelIndex(from.front()) < 0) continue;
        for (std::size_t c = 0; c < var.channels.size(); ++c) {
            const std::size_t component =
                std::min(c, std::size_t(var.components - 1));  // one component fills every channel
            names.push_back(var.channels[c]);
            sources.push_back(var.firstHitAov >= 0
                                  ? Source{&firstHit, firstHit.channelIndex(std::to_string(var.firstHitAov) + "." +
                                                                            std::to_string(component))}
                                  : Source{&film, film.channelIndex(from[component])});
            header.channelTypes.push_back(var.type);
            if (!var.colour) header.dataChannels.push_back(var.channels[c]);
        }
    }
    header.compression = product.compression;
    Image image(window.width(), window.height(), names);
    for (int y = 0; y < window.height(); ++y)
        for (int x = 0; x < window.width(); ++x) {
            float* out = image.pixel(x, y);
            const int fx = x + window.x0 - filmWindow.x0, fy = y + window.y0 - filmWindow.y0;
            for (std::size_t c = 0; c < sources.size(); ++c)
                out[c] = sources[c].image->pixel(fx, fy)[sources[c].channel];
        }
    return image;
}

}  // namespace fluence::app
