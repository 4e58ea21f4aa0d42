#include "delegate/geom_subset.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>

#include "delegate/material_binding.h"
#include "delegate/material_adapter.h"
#include "delegate/mesh_adapter.h"
#include "delegate/motion_samples.h"
#include "delegate/prim_reader.h"

namespace fluence::delegate {

namespace {

bool isActive(const usd::PrimSpec& prim) {
    const usd::MetadataEntry* e = usd::findMetadata(prim.metadata, "active");
    if (!e) return true;
    if (auto b = e->value.asDouble()) return *b != 0.0;
    return e->value.asString().value_or("true") != "false";
}

bool hasBinding(const usd::PrimSpec& prim) {
    for (const char* name : {"material:binding", "material:binding:full"})
        if (const usd::RelationshipSpec* r = prim.relationship(name); r && !r->targets.empty()) return true;
    return false;
}

std::vector<MaterialAssignment::Subset> materialBindSubsets(const usd::Stage& stage, const usd::PrimSpec& mesh,
                                                            double time, std::size_t faceCount,
                                                            const std::function<void(const std::string&)>& warn) {
    std::vector<MaterialAssignment::Subset> subsets;
    for (const auto& child : mesh.children) {
        if (child->typeName != "GeomSubset" || child->specifier != usd::Specifier::Def || !isActive(*child)) continue;
        PrimReader subset(*child, time);
        std::string family = subset.token({"familyName"}, "");
        if (family != "materialBind") {
            if (hasBinding(*child))
                warn("GeomSubset " + child->path + " has a material binding but its familyName is '" + family +
                     "', not 'materialBind'; the binding is ignored");
            continue;
        }
        std::string elementType = subset.token({"elementType"}, "face");
        if (elementType != "face") {
            warn("GeomSubset " + child->path + " has elementType '" + elementType +
                 "'; only face subsets carry materials, so it is ignored");
            continue;
        }
        MaterialAssignment::Subset s;
        s.path = child->path;
        s.materialPath = boundMaterialPath(stage, *child);
        std::vector<double> indices = subset.numbers("indices", 1).value_or(std::vector<double>{});
        s.faces.reserve(indices.size());
        for (std::size_t i = 0; i < indices.size(); ++i) {
            double f = indices[i];
            if (!(f >= 0.0 && f < static_cast<double>(faceCount)) || f != std::floor(f))
                subset.fail("indices[" + std::to_string(i) + "] = " + std::to_string(static_cast<long long>(f)) +
                            " is not a face of " + mesh.path + " (" + std::to_string(faceCount) + " faces)");
            s.faces.push_back(static_cast<std::size_t>(f));
        }
        subsets.push_back(std::move(s));
    }
    return subsets;
}

}  // namespace

MaterialAssignment readMaterialAssignment(const usd::Stage& stage, const usd::PrimSpec& mesh, double time,
                                          std::size_t faceCount, const std::function<void(const std::string&)>& warn) {
    MaterialAssignment a;
    a.meshMaterial = boundMaterialPath(stage, mesh);
    a.subsets = materialBindSubsets(stage, mesh, time, faceCount, warn);
    if (a.subsets.empty()) return a;
    a.subsetOfFace.assign(faceCount, MaterialAssignment::kNoSubset);
    for (std::size_t s = 0; s < a.subsets.size(); ++s) {
        std::size_t overlaps = 0, firstOverlap = 0;
        for (std::size_t f : a.subsets[s].faces) {
            int& owner = a.subsetOfFace[f];
            if (owner == MaterialAssignment::kNoSubset)
                owner = static_cast<int>(s);
            else if (owner != static_cast<int>(s) && overlaps++ == 0)
                firstOverlap = f;
        }
        if (overlaps > 0)
            warn("GeomSubset " + a.subsets[s].path + " lists " + std::to_string(overlaps) +
                 (overlaps == 1 ? " face" : " faces") + " (first: face " + std::to_string(firstOverlap) +
                 ") already in an earlier materialBind subset (" +
                 a.subsets[static_cast<std::size_t>(a.subsetOfFace[firstOverlap])].path + "), which keeps them");
    }
    return a;
}

std::vector<MeshPart> splitByMaterial(TriangulatedMesh&& whole, const MaterialAssignment& assignment) {
    if (assignment.subsets.empty()) {
        std::vector<MeshPart> parts;
        parts.push_back({std::move(whole.mesh), assignment.meshMaterial});
        return parts;
    }
    const std::string& meshMaterial = assignment.meshMaterial;
    const auto& subsets = assignment.subsets;
    const auto& subsetOfFace = assignment.subsetOfFace;
    constexpr int kNoSubset = MaterialAssignment::kNoSubset;

    // Parts by material: the mesh's own first, then in the order subsets bring new ones.
    const render::MeshDesc& mesh = whole.mesh;
    std::vector<MeshPart> parts(1);
    parts[0].mesh.name = mesh.name;
    parts[0].materialPath = meshMaterial;
    std::map<std::string, std::size_t> partOfMaterial{{meshMaterial, 0}};
    std::vector<std::size_t> partOfSubset;
    for (const MaterialAssignment::Subset& s : subsets) {
        auto [it, inserted] = partOfMaterial.try_emplace(s.materialPath, parts.size());
        if (inserted) {
            parts.emplace_back();
            parts.back().mesh.name = s.path;
            parts.back().materialPath = s.materialPath;
        }
        partOfSubset.push_back(it->second);
    }
    for (MeshPart& part : parts)
        for (const render::CornerPrimvar& pv : mesh.primvars)
            part.mesh.primvars.push_back({pv.name, pv.components, {}});

    // Copy each triangle into its part, renumbering the points each part uses.
    constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::vector<std::uint32_t>> newIndex(parts.size());
    const std::size_t triangles = mesh.indices.size() / 3;
    for (std::size_t t = 0; t < triangles; ++t) {
        int subset = subsetOfFace[whole.triangleFaces[t]];
        std::size_t p = subset == kNoSubset ? 0 : partOfSubset[static_cast<std::size_t>(subset)];
        render::MeshDesc& part = parts[p].mesh;
        std::vector<std::uint32_t>& renumber = newIndex[p];
        if (renumber.empty()) renumber.assign(mesh.positions.size(), kUnused);
        for (std::size_t c = 3 * t; c < 3 * t + 3; ++c) {
            std::uint32_t& i = renumber[mesh.indices[c]];
            if (i == kUnused) {
                i = static_cast<std::uint32_t>(part.positions.size());
                part.positions.push_back(mesh.positions[mesh.indices[c]]);
            }
            part.indices.push_back(i);
            if (!mesh.cornerNormals.empty()) part.cornerNormals.push_back(mesh.cornerNormals[c]);
            if (!mesh.cornerColors.empty()) part.cornerColors.push_back(mesh.cornerColors[c]);
            for (std::size_t i = 0; i < mesh.primvars.size(); ++i) {
                const std::size_t k = static_cast<std::size_t>(mesh.primvars[i].components);
                const float* v = &mesh.primvars[i].values[c * k];
                part.primvars[i].values.insert(part.primvars[i].values.end(), v, v + k);
            }
        }
    }
    std::erase_if(parts, [](const MeshPart& part) { return part.mesh.indices.empty(); });
    return parts;
}

std::vector<MeshPart> meshPartsFromPrim(const usd::Stage& stage, const usd::PrimSpec& prim, double time,
                                        const Matrix4& toWorld,
                                        const std::function<RGB(const RGB&, const std::string&)>& convertColor,
                                        const std::function<void(const std::string&)>& warn, double velocityFrame) {
    TriangulatedMesh whole = triangulatedMeshFromPrim(PrimReader(prim, time), toWorld, convertColor);
    moveByVelocities(stage, prim, time, velocityFrame, toWorld, whole.mesh.positions);
    MaterialAssignment assignment = readMaterialAssignment(stage, prim, time, whole.faceCount, warn);
    return splitByMaterial(std::move(whole), assignment);
}

}  // namespace fluence::delegate
