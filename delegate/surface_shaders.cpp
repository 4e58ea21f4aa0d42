#include "delegate/surface_shaders.h"

#include "delegate/shading_network.h"
#include "media/subsurface_medium.h"
#include "render/subsurface_method.h"

#include <algorithm>
#include <cmath>

namespace fluence::delegate {

namespace {

// Displacement is geometry: its binding leaves the per-hit bindings for the delegate's dicing.
void separateDisplacement(render::MaterialDesc& m) {
    auto displaces = [](const render::InputBinding& b) { return b.input == render::MaterialInput::Displacement; };
    auto it = std::find_if(m.bindings.begin(), m.bindings.end(), displaces);
    if (it == m.bindings.end()) return;
    m.displacementBinding = std::move(*it);
    m.bindings.erase(it);
}

}  // namespace

media::MediumProperties transmissionMedium(const RGB& color, const RGB& scatter, float anisotropy, float depth) {
    media::MediumProperties m;
    RGB sigmaT;
    for (int c = 0; c < 3; ++c) sigmaT[c] = -std::log(std::clamp(color[c], kMinTransmissionColor, 1.0f)) / depth;
    m.sigmaS = vmax(scatter, RGB(0.0f)) / depth;
    m.sigmaA = sigmaT - m.sigmaS;
    const float lowest = std::min({m.sigmaA.x, m.sigmaA.y, m.sigmaA.z});
    if (lowest < 0.0f) m.sigmaA -= RGB(lowest);
    m.g = std::clamp(anisotropy, -kMaxInteriorAnisotropy, kMaxInteriorAnisotropy);
    return m;
}

render::MaterialDesc previewSurface(const ShaderInputs& in, const std::string& materialPath) {
    render::MaterialDesc m;
    m.name = materialPath;
    m.diffuse = in.color("diffuseColor", RGB(0.18f));
    m.emission = in.color("emissiveColor", RGB(0.0f));
    m.specularWorkflow = in.flag("useSpecularWorkflow", false);
    if (m.specularWorkflow)
        m.specularColor = in.color("specularColor", RGB(0.0f));
    else
        m.metallic = in.number("metallic", 0.0f);
    m.roughness = in.number("roughness", 0.5f);
    m.coat = in.number("clearcoat", 0.0f);
    m.coatRoughness = in.number("clearcoatRoughness", 0.01f);
    m.opacity = in.number("opacity", 1.0f);
    m.opacityThreshold = in.number("opacityThreshold", 0.0f);
    m.ior = in.number("ior", 1.5f);
    m.displacement = in.number("displacement", 0.0f);
    using render::MaterialInput;
    // The specular workflow reads specularColor and not metallic; the metallic workflow the reverse.
    const DrivableInput workflowInput = m.specularWorkflow
                                            ? DrivableInput{"specularColor", MaterialInput::SpecularColor, 3}
                                            : DrivableInput{"metallic", MaterialInput::Metallic, 1};
    readBindings(in,
                 {{"diffuseColor", MaterialInput::Diffuse, 3},
                  {"emissiveColor", MaterialInput::Emission, 3},
                  workflowInput,
                  {"roughness", MaterialInput::Roughness, 1},
                  {"clearcoat", MaterialInput::Coat, 1},
                  {"clearcoatRoughness", MaterialInput::CoatRoughness, 1},
                  {"opacity", MaterialInput::Opacity, 1},
                  {"ior", MaterialInput::Ior, 1},
                  {"normal", MaterialInput::Normal, 3},
                  {"displacement", MaterialInput::Displacement, 1}},
                 m);
    separateDisplacement(m);
    return m;
}

render::MaterialDesc standardSurface(const ShaderInputs& in, const std::string& materialPath) {
    render::MaterialDesc m;
    m.name = materialPath;
    m.diffuse = in.color("base_color", RGB(1.0f)) * in.number("base", 0.8f);
    m.diffuseRoughness = in.number("diffuse_roughness", 0.0f);
    m.metallic = in.number("metalness", 0.0f);
    m.specular = in.number("specular", 1.0f);
    m.specularColor = in.color("specular_color", RGB(1.0f));
    m.roughness = in.number("specular_roughness", 0.2f);
    m.ior = in.number("specular_IOR", 1.5f);
    m.anisotropy = in.number("specular_anisotropy", 0.0f);
    m.transmission = in.number("transmission", 0.0f);
    m.transmissionColor = in.color("transmission_color", RGB(1.0f));
    m.sheen = in.number("sheen", 0.0f);
    m.sheenColor = in.color("sheen_color", RGB(1.0f));
    m.sheenRoughness = in.number("sheen_roughness", 0.3f);
    m.coat = in.number("coat", 0.0f);
    m.coatColor = in.color("coat_color", RGB(1.0f));
    m.coatRoughness = in.number("coat_roughness", 0.1f);
    m.coatIor = in.number("coat_IOR", 1.5f);
    m.emission = in.color("emission_color", RGB(1.0f)) * in.number("emission", 0.0f);
    RGB opacity = in.color("opacity", RGB(1.0f));
    m.opacity = (opacity.x + opacity.y + opacity.z) / 3.0f;
    m.thinWalled = in.flag("thin_walled", false);
    m.subsurface = in.number("subsurface", 0.0f);
    m.subsurfaceColor = in.color("subsurface_color", RGB(1.0f));
    m.subsurfaceRadius = in.color("subsurface_radius", RGB(1.0f));
    m.subsurfaceScale = in.number("subsurface_scale", 1.0f);
    using render::MaterialInput;
    // Standard Surface's weights multiply their colours: a node drives the colour, and the weight
    // stays its factor (base for base_color, emission for emission_color).
    const float base = in.number("base", 0.8f), emission = in.number("emission", 0.0f);
    readBindings(in,
                 {{"base_color", MaterialInput::Diffuse, 3, base},
                  {"metalness", MaterialInput::Metallic, 1},
                  {"specular", MaterialInput::Specular, 1},
                  {"specular_color", MaterialInput::SpecularColor, 3},
                  {"specular_roughness", MaterialInput::Roughness, 1},
                  {"specular_IOR", MaterialInput::Ior, 1},
                  {"transmission", MaterialInput::Transmission, 1},
                  {"transmission_color", MaterialInput::TransmissionColor, 3},
                  {"sheen", MaterialInput::Sheen, 1},
                  {"sheen_color", MaterialInput::SheenColor, 3},
                  {"coat", MaterialInput::Coat, 1},
                  {"coat_color", MaterialInput::CoatColor, 3},
                  {"coat_roughness", MaterialInput::CoatRoughness, 1},
                  {"emission_color", MaterialInput::Emission, 3, emission},
                  {"opacity", MaterialInput::Opacity, 1},
                  // Read as the tangent-space normal a normalmap node (ND_normalmap) produces.
                  {"normal", MaterialInput::Normal, 3}},
                 m);
    const float depth = in.number("transmission_depth", 0.0f);
    if (depth > 0.0f && !m.thinWalled) {  // transmission_color is reached at that depth inside
        m.interior = transmissionMedium(m.transmissionColor, in.color("transmission_scatter", RGB(0.0f)),
                                        in.number("transmission_scatter_anisotropy", 0.0f), depth);
        m.transmissionColor = RGB(1.0f);
    }
    const std::string method = in.text("subsurface_type", "randomwalk_guided");
    const std::optional<render::SubsurfaceMethod> named =
        render::subsurfaceMethodNamed(method == "randomwalk_v2" ? "randomwalk" : method);
    if (!named)
        in.warn()(in.shader().path, "subsurface_type '" + method + "' is not " +
                                        std::string(render::kSubsurfaceMethodNames) + "; using randomwalk_guided");
    m.subsurfaceMethod = named.value_or(render::SubsurfaceMethod::RandomWalkGuided);
    if (m.subsurface > 0.0f && !m.thinWalled &&
        !m.interior)  // the random walk's medium (diffusion: the probes' material)
        m.interior = media::subsurfaceMedium(m.subsurfaceColor, m.subsurfaceRadius * m.subsurfaceScale,
                                             in.number("subsurface_anisotropy", 0.0f));
    if (m.interior && std::erase_if(m.bindings, [](const render::InputBinding& b) {
                          return b.input == MaterialInput::TransmissionColor;
                      }) > 0)
        in.warn()(in.shader().path,
                  "transmission_color driven by a node with transmission_depth > 0: the interior medium uses its "
                  "constant value");
    return m;
}

}  // namespace fluence::delegate
