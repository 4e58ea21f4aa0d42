#include "delegate/surface_shaders.h"

namespace fluence::delegate {

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
    return m;
}

}  // namespace fluence::delegate
