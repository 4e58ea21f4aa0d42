// Small render-core scenes built in C++ (no USD), for integrator tests.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/sampling.h"
#include "render/scene_description.h"

namespace fluence::test {

// A Lambertian material (no specular lobe), optionally emissive.
inline render::MaterialDesc diffuseMaterial(std::string name, const RGB& albedo, const RGB& emission = RGB(0.0f)) {
    render::MaterialDesc m;
    m.name = std::move(name);
    m.specular = 0.0f;
    m.diffuse = albedo;
    m.emission = emission;
    return m;
}

// A UV sphere with flat facets (no shading normals), so that it is an exactly convex polyhedron.
inline render::MeshDesc sphereMesh(float radius, int segments, int rings, int material) {
    render::MeshDesc m;
    m.name = "/sphere";
    m.material = material;
    const double pi = 3.14159265358979323846;
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s <= segments; ++s) {
            double theta = pi * r / rings, phi = 2 * pi * s / segments;
            m.positions.emplace_back(float(radius * std::sin(theta) * std::cos(phi)),
                                     float(radius * std::sin(theta) * std::sin(phi)), float(radius * std::cos(theta)));
        }
    auto at = [&](int r, int s) { return std::uint32_t(r * (segments + 1) + s); };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            if (r > 0) m.indices.insert(m.indices.end(), {at(r, s), at(r + 1, s), at(r, s + 1)});
            if (r < rings - 1) m.indices.insert(m.indices.end(), {at(r, s + 1), at(r + 1, s), at(r + 1, s + 1)});
        }
    return m;
}

// Round shading normals for a mesh whose points lie on a sphere about the origin (sphereMesh's):
// each corner's normal is the direction of its point from the origin, so that to its BSDFs the
// mesh is a round sphere. Give them before moving the mesh.
inline void addRoundNormals(render::MeshDesc& m) {
    for (std::uint32_t i : m.indices) m.cornerNormals.push_back(normalize(m.positions[i]));
}

// A UV sphere (sphereMesh) with round shading normals (addRoundNormals).
inline render::MeshDesc roundSphereMesh(float radius, int segments, int rings, int material) {
    render::MeshDesc m = sphereMesh(radius, segments, rings, material);
    addRoundNormals(m);
    return m;
}

// The same, centred at `centre`.
inline render::MeshDesc roundSphereMesh(float radius, int segments, int rings, int material, const Vec3f& centre) {
    render::MeshDesc m = roundSphereMesh(radius, segments, rings, material);
    for (Vec3f& p : m.positions) p += centre;
    return m;
}

// A metal (MaterialParams::metallic = 1) of reflectance `colour` at normal incidence.
inline render::MaterialDesc metalMaterial(std::string name, const RGB& colour, float roughness) {
    render::MaterialDesc m;
    m.name = std::move(name);
    m.diffuse = colour;
    m.metallic = 1.0f;
    m.roughness = roughness;
    return m;
}

// Clear glass (a solid of ior 1.5, transmission 1).
inline render::MaterialDesc glassMaterial(std::string name, float roughness) {
    render::MaterialDesc m;
    m.name = std::move(name);
    m.transmission = 1.0f;
    m.roughness = roughness;
    return m;
}

// A thin-walled sheet, partly transmissive, over a diffuse `colour`.
inline render::MaterialDesc thinSheetMaterial(std::string name, const RGB& colour, float transmission,
                                              float roughness) {
    render::MaterialDesc m;
    m.name = std::move(name);
    m.diffuse = colour;
    m.transmission = transmission;
    m.thinWalled = true;
    m.roughness = roughness;
    return m;
}

// A quad (two triangles) with corners in order around it.
inline render::MeshDesc quadMesh(std::string name, const std::array<Vec3f, 4>& corners, int material) {
    render::MeshDesc m;
    m.name = std::move(name);
    m.material = material;
    m.positions.assign(corners.begin(), corners.end());
    m.indices = {0, 1, 2, 0, 2, 3};
    return m;
}

// The box [-halfSize, halfSize] (per axis) as 12 triangles wound counter-clockwise seen from
// outside, so its geometric normals face out.
inline render::MeshDesc boxMesh(const Vec3f& halfSize, int material) {
    render::MeshDesc m;
    m.name = "/Box";
    m.material = material;
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {-1.0f, 1.0f}) {
            Vec3f n(0.0f), u(0.0f), v(0.0f);
            n[axis] = side;
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = side;  // u x v = n
            auto base = static_cast<std::uint32_t>(m.positions.size());
            for (auto [a, b] :
                 {std::pair(-1.0f, -1.0f), std::pair(1.0f, -1.0f), std::pair(1.0f, 1.0f), std::pair(-1.0f, 1.0f)})
                m.positions.push_back((n + u * a + v * b) * halfSize);
            for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
        }
    return m;
}

// A torus about the Z axis (ring radius `ring`, tube radius `tube`), closed and wound outwards,
// with round shading normals: a shape with a concave inside.
inline render::MeshDesc torusMesh(float ring, float tube, int segments, int sides, int material) {
    render::MeshDesc m;
    m.name = "/Torus";
    m.material = material;
    std::vector<Vec3f> normals;
    for (int i = 0; i < segments; ++i)
        for (int j = 0; j < sides; ++j) {
            const float u = 2.0f * kPi * i / segments, v = 2.0f * kPi * j / sides;
            const Vec3f n(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v));
            m.positions.push_back(Vec3f(ring * std::cos(u), ring * std::sin(u), 0.0f) + n * tube);
            normals.push_back(n);
        }
    auto index = [&](int i, int j) { return static_cast<std::uint32_t>((i % segments) * sides + j % sides); };
    for (int i = 0; i < segments; ++i)
        for (int j = 0; j < sides; ++j)
            for (std::uint32_t k : {index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j), index(i + 1, j + 1),
                                    index(i, j + 1)}) {
                m.indices.push_back(k);
                m.cornerNormals.push_back(normals[k]);
            }
    return m;
}

// A camera at distance `distance` on -Y looking at the origin, Z up, with a vertical FOV that
// frames the unit sphere.
inline render::CameraDesc lookAtOriginCamera(float distance) {
    render::CameraDesc c;
    c.focalLength = 50.0f;
    c.horizontalAperture = 36.0f;
    c.verticalAperture = 36.0f;
    c.nearClip = 0.01f;
    c.farClip = 1000.0f;
    // Camera looks along local -Z with +Y up: rotate so -Z -> +Y and +Y -> +Z.
    c.transform = Matrix4::translate({0, -distance, 0}) * Matrix4::rotateX(90);
    return c;
}

// ---- Lights. Each builder sets a light's name, kind, radiance and placement (lights emit along
// their local -Z) and what its kind needs; every other field keeps LightDesc's default
// (render/scene_description.h), for a test to set on the result.

// A light of kind `type` placed by `transform`.
inline render::LightDesc lightDesc(std::string name, render::LightType type, const RGB& radiance,
                                   const Matrix4& transform = Matrix4::identity()) {
    render::LightDesc l;
    l.name = std::move(name);
    l.type = type;
    l.radiance = radiance;
    l.transform = transform;
    return l;
}

// A sphere light of the given radius centred at `position`.
inline render::LightDesc sphereLight(std::string name, float radius, const RGB& radiance,
                                     const Vec3d& position = Vec3d(0.0)) {
    render::LightDesc l = lightDesc(std::move(name), render::LightType::Sphere, radiance, Matrix4::translate(position));
    l.radius = radius;
    return l;
}

// A point light at `position`: a sphere light of radius 0.05 rendered as a point of the same
// power (treatAsPoint).
inline render::LightDesc pointLight(std::string name, const RGB& radiance, const Vec3d& position = Vec3d(0.0)) {
    render::LightDesc l = sphereLight(std::move(name), 0.05f, radiance, position);
    l.treatAsPoint = true;
    return l;
}

// A width x height rect light placed by `transform`.
inline render::LightDesc rectLight(std::string name, float width, float height, const RGB& radiance,
                                   const Matrix4& transform) {
    render::LightDesc l = lightDesc(std::move(name), render::LightType::Rect, radiance, transform);
    l.width = width;
    l.height = height;
    return l;
}

// A disk light of the given radius placed by `transform`.
inline render::LightDesc diskLight(std::string name, float radius, const RGB& radiance, const Matrix4& transform) {
    render::LightDesc l = lightDesc(std::move(name), render::LightType::Disk, radiance, transform);
    l.radius = radius;
    return l;
}

// A distant light (a sun) of angular diameter `angleDegrees` (0: a delta light), shining along
// the local -Z of `transform`.
inline render::LightDesc distantLight(std::string name, float angleDegrees, const RGB& radiance,
                                      const Matrix4& transform) {
    render::LightDesc l = lightDesc(std::move(name), render::LightType::Distant, radiance, transform);
    l.angleDegrees = angleDegrees;
    return l;
}

// A dome light of constant radiance (no texture).
inline render::LightDesc domeLight(std::string name, const RGB& radiance) {
    return lightDesc(std::move(name), render::LightType::Dome, radiance);
}

// A furnace: a sphere of the given albedo inside a dome of radiance 1.
inline render::SceneDescription furnaceScene(float albedo) {
    render::SceneDescription s;
    s.materials.push_back(diffuseMaterial("/mat", RGB(albedo)));
    s.meshes.push_back(sphereMesh(1.0f, 48, 24, 0));
    s.lights.push_back(domeLight("/dome", RGB(1.0f)));
    s.camera = lookAtOriginCamera(4.0f);
    return s;
}

// The furnace's sphere (albedo 0.6) lit by a small, bright sphere light under a dim sky: the sky
// seen directly has no noise at all, the sphere's lit and shadowed sides plenty, so adaptive
// sampling stops pixels at many different counts. Next-event estimation chooses between the sky
// and the bulb (domeLightSampling always): under the default policy the convex sphere's light is
// nearly noise-free (the constant sky gathered exactly by its cosine-sampled rays, the bulb by
// cone sampling), and every pixel would stop at the minimum.
inline render::SceneDescription litSphereUnderASky() {
    render::SceneDescription s = furnaceScene(0.6f);
    s.domeLightSampling = render::DomeLightSampling::Always;
    s.lights[0].radiance = RGB(0.2f);
    render::LightDesc bulb;
    bulb.name = "/bulb";
    bulb.type = render::LightType::Sphere;
    bulb.radius = 0.1f;
    bulb.radiance = RGB(400.0f);
    bulb.transform = Matrix4::translate({2.0, -2.0, 2.0});
    s.lights.push_back(bulb);
    return s;
}

}  // namespace fluence::test
