#include "delegate/displacement.h"

#include <array>
#include <bit>
#include <cstdint>
#include <unordered_map>

namespace fluence::delegate {

namespace {

render::MaterialDesc displacementOnly(const render::MaterialDesc& material) {
    render::MaterialDesc out;
    out.name = material.name;
    out.displacement = material.displacement;
    if (material.displacementBinding) out.bindings.push_back(*material.displacementBinding);
    return out;
}

// A position's exact bits, to weld vertices that coincide.
struct PositionKey {
    std::array<std::uint32_t, 3> bits;
    bool operator==(const PositionKey&) const = default;
};

struct PositionHash {
    std::size_t operator()(const PositionKey& k) const {
        std::size_t h = 0;
        for (std::uint32_t b : k.bits) h = h * 0x9E3779B97F4A7C15ull + b;
        return h;
    }
};

PositionKey keyOf(const Vec3f& p) {
    return {std::bit_cast<std::uint32_t>(p.x + 0.0f), std::bit_cast<std::uint32_t>(p.y + 0.0f),
            std::bit_cast<std::uint32_t>(p.z + 0.0f)};  // + 0: -0 and 0 weld
}

}  // namespace

bool MaterialDisplacement::displaces(const render::MaterialDesc& material) {
    return material.displacement != 0.0f || material.displacementBinding.has_value();
}

MaterialDisplacement::MaterialDisplacement(const render::MaterialDesc& material, texture::TextureSystem* textures,
                                           std::vector<render::Warning>& warnings)
    : material_(displacementOnly(material)), shader_(material_, textures, warnings) {}

void MaterialDisplacement::atVertices(const render::MeshDesc& mesh, const std::function<bool(std::size_t)>& where,
                                      std::vector<float>& amounts) const {
    if (!shader_.hasBindings()) {
        for (std::size_t v = 0; v < amounts.size(); ++v)
            if (where(v)) amounts[v] = material_.displacement;
        return;
    }
    std::vector<const render::CornerPrimvar*> primvars;
    for (const std::string& slot : shader_.primvarSlots()) {
        const render::CornerPrimvar* found = nullptr;
        for (const render::CornerPrimvar& pv : mesh.primvars)
            if (pv.name == slot) found = &pv;
        primvars.push_back(found);
    }
    std::vector<bool> done(amounts.size(), false);
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        const std::size_t v = mesh.indices[c];
        if (done[v] || !where(v)) continue;
        done[v] = true;
        render::ShadingPatch patch;
        patch.corner = c - c % 3;
        patch.b0 = c % 3 == 0 ? 1.0f : 0.0f;
        patch.b1 = c % 3 == 1 ? 1.0f : 0.0f;
        patch.b2 = c % 3 == 2 ? 1.0f : 0.0f;
        render::MaterialParams params;
        Vec3f normal(0.0f, 0.0f, 1.0f), tangent(0.0f);
        shader_.evaluate(patch, primvars.data(), params, normal, tangent);
        amounts[v] = params.displacement;
    }
}

const MaterialDisplacement* MaterialDisplacements::of(const render::MaterialDesc& material) {
    if (!MaterialDisplacement::displaces(material)) return nullptr;
    auto [it, inserted] = built_.try_emplace(material.name);
    if (inserted) {
        std::vector<render::Warning> warnings;
        it->second = std::make_unique<MaterialDisplacement>(material, textures_, warnings);
        for (const render::Warning& w : warnings) warn_(w.where, "displacement: " + w.message);
    }
    return it->second.get();
}

void displaceAlongNormals(render::MeshDesc& mesh, const std::vector<Vec3f>& normals,
                          const std::vector<float>& amounts) {
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
        if (amounts[v] != 0.0f) mesh.positions[v] = mesh.positions[v] + normals[v] * amounts[v];
    recomputeShadingNormals(mesh);
}

void recomputeShadingNormals(render::MeshDesc& mesh) {
    std::unordered_map<PositionKey, Vec3f, PositionHash> sums;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const Vec3f &a = mesh.positions[mesh.indices[t]], &b = mesh.positions[mesh.indices[t + 1]],
                    &c = mesh.positions[mesh.indices[t + 2]];
        const Vec3f n = cross(b - a, c - a);  // twice the area, along the normal
        for (const Vec3f* p : {&a, &b, &c}) {
            auto [it, inserted] = sums.try_emplace(keyOf(*p), Vec3f(0.0f));
            it->second = it->second + n;
        }
    }
    mesh.cornerNormals.assign(mesh.indices.size(), Vec3f(0.0f));
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        const Vec3f& sum = sums.at(keyOf(mesh.positions[mesh.indices[c]]));
        if (lengthSquared(sum) > 0.0f) {
            mesh.cornerNormals[c] = normalize(sum);
        } else {  // only degenerate triangles meet here: their own (possibly zero) normal
            const std::size_t t = c - c % 3;
            const Vec3f &a = mesh.positions[mesh.indices[t]], &b = mesh.positions[mesh.indices[t + 1]],
                        &d = mesh.positions[mesh.indices[t + 2]];
            const Vec3f n = cross(b - a, d - a);
            mesh.cornerNormals[c] = lengthSquared(n) > 0.0f ? normalize(n) : Vec3f(0.0f, 0.0f, 1.0f);
        }
    }
}

}  // namespace fluence::delegate
